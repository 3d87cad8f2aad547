#include "forward.hpp"

#include "forward_material.hpp"

namespace sg::passes {

ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets) {
  auto& pass = graph.addPass("forward-opaque", graph::QueueClass::Graphics);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  pass.read(targets.depth, graph::Access::DepthRead);
  pass.execute([view, targets](PassContext& ctx) {
    const auto& pipeline = forwardPipeline(ctx, view, false);
    ctx.beginRendering({ColorTarget{targets.color, VkClearColorValue{{0.42f, 0.55f, 0.75f, 1.0f}}}},
                       DepthTarget{targets.depth, {}, true}, true);
    ctx.bind(pipeline, {{0, gpu::BufferBinding{view.frameUniforms.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    for (uint32_t d : view.draws)
      if (view.scene.draws()[d].alphaMode == scene::AlphaMode::Opaque) drawWithMaterial(ctx, pipeline, view, d);
    ctx.endRendering();
  });
  return targets;
}

}  // namespace sg::passes
