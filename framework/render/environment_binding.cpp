#include <shadelgraph/render/environment_binding.hpp>

#include <shadelgraph/render/shaders/frame_interface.h>

namespace sg::render {
namespace {

struct Map {
  uint32_t binding;
  const char* resource;
};
constexpr Map kMaps[3] = {{shader::kBindEnvironmentIrradiance, kEnvironmentIrradianceResource},
                          {shader::kBindEnvironmentSpecular, kEnvironmentSpecularResource},
                          {shader::kBindEnvironmentBrdf, kEnvironmentBrdfResource}};

}  // namespace

std::array<gpu::DescriptorBinding, 3> environmentBindings() {
  std::array<gpu::DescriptorBinding, 3> out;
  for (size_t i = 0; i < 3; ++i) out[i] = {kMaps[i].binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER};
  return out;
}

void readEnvironment(graph::Pass& pass, const SceneView& view, graph::ShaderStage stage) {
  for (const Map& m : kMaps)
    if (const auto it = view.frameImages.find(m.resource); it != view.frameImages.end())
      pass.read(it->second, graph::Access::Sampled, stage);
}

std::array<gpu::DescriptorWrite, 3> environmentWrites(PassContext& ctx, const SceneView& view) {
  std::array<gpu::DescriptorWrite, 3> out;
  for (size_t i = 0; i < 3; ++i) {
    const auto it = view.frameImages.find(kMaps[i].resource);
    const VkImageView image = it != view.frameImages.end() ? ctx.image(it->second).view() : view.scene.whiteView();
    out[i] = {kMaps[i].binding,
              gpu::ImageBinding{image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, ctx.device().nearestSampler()}};
  }
  return out;
}

}  // namespace sg::render
