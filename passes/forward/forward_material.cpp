#include "forward_material.hpp"

#include <algorithm>

namespace sg::passes {

const gpu::Pipeline& forwardPipeline(PassContext& ctx, const render::SceneView& view, bool blend) {
  return ctx.device().pipeline(blend ? "forward/blend" : "forward", [&] {
    return gpu::GraphicsPipelineDesc{
        .vertex = {.path = "passes/forward/forward.vert"},
        .fragment = {.path = "passes/forward/forward.frag"},
        .layout = {.bindings = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                   .extraSets = {view.scene.materialSetLayout()},
                   .pushConstantBytes = sizeof(render::ObjectConstants)},
        .vertexInput = render::sceneVertexInput(),
        .colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT},
        .depthFormat = VK_FORMAT_D32_SFLOAT,
        .depthTest = true,
        .depthWrite = !blend,
        .alphaBlend = blend};
  });
}

void drawWithMaterial(PassContext& ctx, const gpu::Pipeline& pipeline, const render::SceneView& view, uint32_t draw) {
  const auto& item = view.scene.draws()[draw];
  VkDescriptorSet set = view.scene.materialSet(item.material);
  vkCmdBindDescriptorSets(ctx.cmd(), VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 1, 1, &set, 0, nullptr);
  render::drawItem(ctx.cmd(), pipeline, item, draw);
}

bool hasAlphaMode(const render::SceneView& view, scene::AlphaMode mode) {
  return std::any_of(view.draws.begin(), view.draws.end(),
                     [&](uint32_t d) { return view.scene.draws()[d].alphaMode == mode; });
}

}  // namespace sg::passes
