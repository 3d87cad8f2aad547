#include "z_prepass.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

// The opaque draws of `view`, each from command `d` of `indirect` when it is set.
void drawOpaque(PassContext& ctx, const render::SceneView& view, VkBuffer indirect) {
  const auto& pipeline = ctx.device().pipeline("z-prepass", zPrepassPipeline);
  ctx.bind(pipeline, {{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}}});
  view.scene.bindGeometry(ctx.cmd());
  const auto& draws = view.scene.draws();
  for (uint32_t i : view.draws)
    if (draws[i].alphaMode == scene::AlphaMode::Opaque) render::drawItem(ctx.cmd(), pipeline, draws[i], i, indirect, i);
}

}  // namespace

gpu::GraphicsPipelineDesc zPrepassPipeline() {
  return {.vertex = {.path = "passes/z-prepass/z_prepass.vert"},
          .layout = {.bindings = {{shader::kBindFrame, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER}},
                     .pushConstantBytes = sizeof(render::ObjectConstants)},
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = true};
}

graph::ResourceHandle addZPrepass(graph::RenderGraph& graph, const render::SceneView& view, graph::ResourceHandle depth) {
  auto& pass = graph.addPass("z-prepass", graph::QueueClass::Graphics);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), depth](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{depth, 1.0f}, true);
    drawOpaque(ctx, view, view.indirect);
    ctx.endRendering();
  });
  return depth;
}

graph::ResourceHandle addZPrepassLate(graph::RenderGraph& graph, const render::SceneView& view,
                                      graph::ResourceHandle depth, graph::ResourceHandle late) {
  auto& pass = graph.addPass("z-prepass (late)", graph::QueueClass::Graphics);
  pass.read(late, graph::Access::IndirectArgs);
  render::readSceneGeometry(pass, view);
  depth = pass.write(depth, graph::Access::DepthAttachment);
  pass.execute([view, depth, late](PassContext& ctx) {
    ctx.beginRendering({}, DepthTarget{depth, {}}, true);
    drawOpaque(ctx, view, ctx.buffer(late).handle());
    ctx.endRendering();
  });
  return depth;
}

}  // namespace sg::passes
