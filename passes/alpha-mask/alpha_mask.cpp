#include "alpha_mask.hpp"

#include "forward/forward_material.hpp"

namespace sg::passes {

ForwardTargets addAlphaMask(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets) {
  auto& pass = graph.addPass("alpha-mask", graph::QueueClass::Graphics);
  pass.read(targets.color, graph::Access::ColorAttachmentRead);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  pass.execute([view, targets](PassContext& ctx) {
    const auto& pipeline = forwardPipeline(ctx, view, false);
    ctx.beginRendering({ColorTarget{targets.color}}, DepthTarget{targets.depth}, true);
    ctx.bind(pipeline, {{0, gpu::BufferBinding{view.frameUniforms.handle()}}});
    view.scene.bindGeometry(ctx.cmd());
    for (uint32_t d : view.draws)
      if (view.scene.draws()[d].alphaMode == scene::AlphaMode::Mask) drawWithMaterial(ctx, pipeline, view, d);
    ctx.endRendering();
  });
  return targets;
}

}  // namespace sg::passes
