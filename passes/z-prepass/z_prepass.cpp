#include "z_prepass.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

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
  pass.execute([view, depth](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("z-prepass", zPrepassPipeline);
    ctx.beginRendering({}, DepthTarget{depth, 1.0f}, true);
    ctx.bind(pipeline, {{shader::kBindFrame, gpu::BufferBinding{view.frameUniforms.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    const auto& draws = view.scene.draws();
    for (uint32_t i : view.draws)
      if (draws[i].alphaMode == scene::AlphaMode::Opaque) render::drawItem(ctx.cmd(), pipeline, draws[i], i);
    ctx.endRendering();
  });
  return depth;
}

}  // namespace sg::passes
