#include <shadelgraph/gpu/readback.hpp>

#include <utility>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/gpu/image.hpp>

namespace sg::gpu {

HostImage readImage(Context& context, MemoryAllocator& memory, const Image& image, VkImageLayout layout) {
  const auto& d = image.desc();
  const bool bgra = d.format == VK_FORMAT_B8G8R8A8_UNORM || d.format == VK_FORMAT_B8G8R8A8_SRGB;
  if (!bgra && d.format != VK_FORMAT_R8G8B8A8_UNORM && d.format != VK_FORMAT_R8G8B8A8_SRGB)
    throw GpuError("readImage: only 8-bit RGBA/BGRA images can be read back");
  Buffer staging(context, memory,
                 {size_t(d.width) * d.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryLocation::Readback,
                  "readback", "staging"});
  context.submitAndWait([&](VkCommandBuffer cmd) {
    const Scope copyRead{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
    imageBarrier(cmd, image.handle(), layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT}, copyRead, 0, 1);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {d.width, d.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    if (layout != VK_IMAGE_LAYOUT_UNDEFINED)
      imageBarrier(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, {VK_PIPELINE_STAGE_2_COPY_BIT},
                   {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT}, 0, 1);
    // Make the copy visible to the host read below.
    hostReadAfterCopy(cmd);
  });
  const auto* bytes = reinterpret_cast<const uint8_t*>(staging.mapped());
  HostImage out{d.width, d.height, std::vector<uint8_t>(bytes, bytes + staging.size())};
  if (bgra)
    for (size_t i = 0; i < out.rgba8.size(); i += 4) std::swap(out.rgba8[i], out.rgba8[i + 2]);
  return out;
}

}  // namespace sg::gpu
