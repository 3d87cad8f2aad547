#include "shadows.hpp"

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/shadow_views.hpp>

namespace sg::passes {
namespace {

// The push constants of shadow_map.vert: the object's, then the light's index.
constexpr uint32_t kLightPushOffset = sizeof(render::ObjectConstants);
constexpr uint32_t kSide = render::kShadowMapResolution;

}  // namespace

gpu::GraphicsPipelineDesc shadowMapPipeline() {
  return {.vertex = {.path = "passes/shadows/shadow_map.vert"},
          .fragment = {.path = "passes/shadows/shadow_map.frag"},
          .layout = {.bindings = {{shader::kBindLights, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                     .pushConstantBytes = kLightPushOffset + uint32_t(sizeof(uint32_t))},
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = true};
}

graph::ResourceHandle addShadowMaps(graph::RenderGraph& graph, const render::SceneView& view,
                                    std::vector<ShadowMapDraws> maps, uint32_t slots) {
  auto atlas = graph.createImage("shadow atlas",
                                 {.format = graph::Format::D32F, .size = graph::Size::absolute(slots * kSide, kSide)});
  auto& pass = graph.addPass("shadows", graph::QueueClass::Graphics);
  atlas = pass.write(atlas, graph::Access::DepthAttachment);
  pass.execute([view, maps = std::move(maps), atlas](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{atlas, 1.0f}, true);
    const auto& pipeline = ctx.device().pipeline("shadow-map", shadowMapPipeline);
    ctx.bind(pipeline, {{shader::kBindLights, gpu::BufferBinding{view.lights.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    const auto& draws = view.scene.draws();
    for (const ShadowMapDraws& map : maps) {
      // The map's column, +Y up like the scene passes (negative height).
      const VkViewport viewport{float(map.slot * kSide), float(kSide), float(kSide), -float(kSide), 0.0f, 1.0f};
      const VkRect2D scissor{{int32_t(map.slot * kSide), 0}, {kSide, kSide}};
      vkCmdSetViewport(ctx.cmd(), 0, 1, &viewport);
      vkCmdSetScissor(ctx.cmd(), 0, 1, &scissor);
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, kLightPushOffset, sizeof map.light,
                         &map.light);
      for (uint32_t d : map.casters) render::drawItem(ctx.cmd(), pipeline, draws[d], d);
    }
    ctx.endRendering();
  });
  return atlas;
}

}  // namespace sg::passes
