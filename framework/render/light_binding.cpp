#include <shadelgraph/render/light_binding.hpp>

#include <shadelgraph/render/shaders/frame_interface.h>

namespace sg::render {

std::array<gpu::DescriptorBinding, 2> lightBindings() {
  return {{{shader::kBindLights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
           {shader::kBindLightGrid, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}};
}

void readLightGrid(graph::Pass& pass, const SceneView& view, graph::ShaderStage stage) {
  if (const auto it = view.frameImages.find(kLightGridResource); it != view.frameImages.end())
    pass.read(it->second, graph::Access::StorageRead, stage);
}

std::array<gpu::DescriptorWrite, 2> lightWrites(PassContext& ctx, const SceneView& view) {
  const auto it = view.frameImages.find(kLightGridResource);
  const VkBuffer grid = it != view.frameImages.end() ? ctx.buffer(it->second).handle() : view.noLightGrid.handle();
  return {{{shader::kBindLights, gpu::BufferBinding{view.lights.handle()}},
           {shader::kBindLightGrid, gpu::BufferBinding{grid}}}};
}

}  // namespace sg::render
