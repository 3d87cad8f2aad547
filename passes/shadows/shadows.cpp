#include "shadows.hpp"

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/render/shadow_views.hpp>

namespace sg::passes {
namespace {

// The push constants of shadow_map.vert: the object's, then the map's slot.
constexpr uint32_t kLightPushOffset = sizeof(render::ObjectConstants);
constexpr uint32_t kSide = render::kShadowMapResolution;

}  // namespace

gpu::GraphicsPipelineDesc shadowMapPipeline() {
  return {.vertex = {.path = "passes/shadows/shadow_map.vert"},
          .fragment = {.path = "passes/shadows/shadow_map.frag"},
          .layout = {.bindings = {{shader::kBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                     .pushConstantBytes = kLightPushOffset + uint32_t(sizeof(uint32_t))},
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = true};
}

graph::ResourceHandle addShadowMaps(graph::RenderGraph& graph, const render::SceneView& view,
                                    std::vector<ShadowMapDraws> maps, uint32_t slots) {
  const glm::uvec2 grid = render::shadowAtlasMaps(slots);
  auto atlas = graph.createImage(
      "shadow atlas", {.format = graph::Format::D32F, .size = graph::Size::absolute(grid.x * kSide, grid.y * kSide)});
  auto& pass = graph.addPass("shadows", graph::QueueClass::Graphics);
  atlas = pass.write(atlas, graph::Access::DepthAttachment);
  render::readSceneGeometry(pass, view);
  pass.execute([view, maps = std::move(maps), atlas](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{atlas, 1.0f}, true);
    const auto& pipeline = ctx.device().pipeline("shadow-map", shadowMapPipeline);
    ctx.bind(pipeline, {{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    const auto& draws = view.scene.draws();
    for (const ShadowMapDraws& map : maps) {
      // The map's square of the atlas, +Y up like the scene passes (negative height).
      const uint32_t x = map.slot % render::kShadowAtlasColumns * kSide, y = map.slot / render::kShadowAtlasColumns * kSide;
      const VkViewport viewport{float(x), float(y + kSide), float(kSide), -float(kSide), 0.0f, 1.0f};
      const VkRect2D scissor{{int32_t(x), int32_t(y)}, {kSide, kSide}};
      vkCmdSetViewport(ctx.cmd(), 0, 1, &viewport);
      vkCmdSetScissor(ctx.cmd(), 0, 1, &scissor);
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, kLightPushOffset, sizeof map.slot,
                         &map.slot);
      for (uint32_t d : map.casters) render::drawItem(ctx.cmd(), pipeline, draws[d], d);
    }
    ctx.endRendering();
  });
  return atlas;
}

}  // namespace sg::passes
