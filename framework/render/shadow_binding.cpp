#include <shadelgraph/render/shadow_binding.hpp>

#include <shadelgraph/render/shaders/frame_interface.h>

namespace sg::render {

gpu::DescriptorBinding shadowMapsBinding() {
  return {shader::kBindShadowMaps, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
}

void readShadowMaps(graph::Pass& pass, const SceneView& view, graph::ShaderStage stage) {
  if (const auto it = view.frameImages.find(kShadowMapsResource); it != view.frameImages.end())
    pass.read(it->second, graph::Access::Sampled, stage);
}

gpu::DescriptorWrite shadowMapsWrite(PassContext& ctx, const SceneView& view) {
  const auto it = view.frameImages.find(kShadowMapsResource);
  const VkImageView image = it != view.frameImages.end() ? ctx.image(it->second).view() : view.scene.whiteView();
  return {shader::kBindShadowMaps,
          gpu::ImageBinding{image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, ctx.device().nearestSampler()}};
}

}  // namespace sg::render
