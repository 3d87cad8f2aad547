#include "alpha_mask.hpp"

#include "forward/forward_material.hpp"

namespace sg::passes {

ForwardTargets addAlphaMask(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                            std::optional<VkClearColorValue> clear) {
  auto& pass = graph.addPass("alpha-mask", graph::QueueClass::Graphics);
  if (!clear) pass.read(targets.color, graph::Access::ColorAttachmentRead);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  readFrameInputs(pass, view, view.draws);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), targets, clear](PassContext& ctx) {
    ctx.beginRendering({ColorTarget{targets.color, clear}}, DepthTarget{targets.depth}, true);
    drawForward(ctx, view, drawsWithAlphaMode(view, scene::AlphaMode::Mask), false);
    ctx.endRendering();
  });
  return targets;
}

}  // namespace sg::passes
