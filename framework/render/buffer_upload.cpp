#include <shadelgraph/render/buffer_upload.hpp>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/context.hpp>

namespace sg::render {

gpu::Buffer uploadBuffer(gpu::Context& context, gpu::MemoryAllocator& memory, const void* data, size_t bytes,
                         VkBufferUsageFlags usage, const char* name, bool concurrent) {
  gpu::Buffer buffer(context, memory, {bytes, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Device, name, "scene geometry", concurrent});
  gpu::Buffer staging(context, memory, {bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryLocation::Upload, name, "staging"});
  staging.write(data, bytes);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer.handle(), 1, &copy);
    gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT});
  });
  return buffer;
}

}  // namespace sg::render
