#include <shadelgraph/gpu/readback.hpp>

#include <utility>

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
    VkImageMemoryBarrier2 toSrc{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    toSrc.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    toSrc.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    toSrc.dstStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    toSrc.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
    toSrc.oldLayout = layout;
    toSrc.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    toSrc.image = image.handle();
    toSrc.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &toSrc;
    vkCmdPipelineBarrier2(cmd, &dep);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {d.width, d.height, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    VkImageMemoryBarrier2 back = toSrc;
    back.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    back.srcAccessMask = 0;
    back.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    back.dstAccessMask = 0;
    back.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    back.newLayout = layout;
    dep.pImageMemoryBarriers = &back;
    if (layout != VK_IMAGE_LAYOUT_UNDEFINED) vkCmdPipelineBarrier2(cmd, &dep);
    // Make the copy visible to the host read below.
    VkMemoryBarrier2 host{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    host.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
    host.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
    host.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
    host.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
    VkDependencyInfo hostDep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    hostDep.memoryBarrierCount = 1;
    hostDep.pMemoryBarriers = &host;
    vkCmdPipelineBarrier2(cmd, &hostDep);
  });
  const auto* bytes = reinterpret_cast<const uint8_t*>(staging.mapped());
  HostImage out{d.width, d.height, std::vector<uint8_t>(bytes, bytes + staging.size())};
  if (bgra)
    for (size_t i = 0; i < out.rgba8.size(); i += 4) std::swap(out.rgba8[i], out.rgba8[i + 2]);
  return out;
}

}  // namespace sg::gpu
