#include <shadelgraph/render/texture_upload.hpp>

#include <algorithm>
#include <bit>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/context.hpp>

namespace sg::render {

uint32_t mipCount(uint32_t w, uint32_t h) { return std::bit_width(std::max(w, h)); }

gpu::Image uploadTexture(gpu::Context& context, gpu::MemoryAllocator& memory, uint32_t w, uint32_t h,
                         const uint8_t* pixels, bool srgb, const std::string& name, const std::string& category) {
  const uint32_t mips = mipCount(w, h);
  gpu::Image image(context, memory,
                   {.width = w, .height = h, .format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM,
                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                    .mipLevels = mips, .name = name, .category = category});
  gpu::Buffer staging(context, memory,
                      {size_t(w) * h * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryLocation::Upload, name, "staging"});
  staging.write(pixels, size_t(w) * h * 4);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    using gpu::Scope;
    const VkImage img = image.handle();
    const Scope write{VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    const Scope blitRead{VK_PIPELINE_STAGE_2_BLIT_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
    const Scope shaderRead{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    gpu::imageBarrier(cmd, img, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, {}, write, 0, mips);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {w, h, 1};
    vkCmdCopyBufferToImage(cmd, staging.handle(), img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    int32_t mw = int32_t(w), mh = int32_t(h);
    for (uint32_t level = 1; level < mips; ++level) {
      gpu::imageBarrier(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, write,
                        blitRead, level - 1, 1);
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
      blit.srcOffsets[1] = {mw, mh, 1};
      mw = std::max(mw / 2, 1);
      mh = std::max(mh / 2, 1);
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
      blit.dstOffsets[1] = {mw, mh, 1};
      vkCmdBlitImage(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                     VK_FILTER_LINEAR);
    }
    if (mips > 1)
      gpu::imageBarrier(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                        {VK_PIPELINE_STAGE_2_BLIT_BIT}, shaderRead, 0, mips - 1);
    gpu::imageBarrier(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, write,
                      shaderRead, mips - 1, 1);
  });
  return image;
}

}  // namespace sg::render
