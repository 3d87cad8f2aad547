#include "forward.hpp"

#include "forward_material.hpp"

namespace sg::passes {

ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets) {
  auto& pass = graph.addPass("forward-opaque", graph::QueueClass::Graphics);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  pass.read(targets.depth, graph::Access::DepthRead);
  readFrameInputs(pass, view, view.draws);
  pass.execute([view = render::readDrawCommands(pass, view), targets](PassContext& ctx) {
    ctx.beginRendering({ColorTarget{targets.color, VkClearColorValue{{0.42f, 0.55f, 0.75f, 1.0f}}}},
                       DepthTarget{targets.depth, {}, true}, true);
    drawForward(ctx, view, drawsWithAlphaMode(view, scene::AlphaMode::Opaque), false);
    ctx.endRendering();
  });
  return targets;
}

ForwardTargets addForwardOpaqueWritingDepth(graph::RenderGraph& graph, const render::SceneView& view,
                                            ForwardTargets targets) {
  auto& pass = graph.addPass("forward-opaque", graph::QueueClass::Graphics);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  readFrameInputs(pass, view, view.draws);
  pass.execute([view = render::readDrawCommands(pass, view), targets](PassContext& ctx) {
    ctx.beginRendering({ColorTarget{targets.color, VkClearColorValue{{0.42f, 0.55f, 0.75f, 1.0f}}}},
                       DepthTarget{targets.depth, 1.0f}, true);
    drawForward(ctx, view, drawsWithAlphaMode(view, scene::AlphaMode::Opaque), false);
    ctx.endRendering();
  });
  return targets;
}

ForwardTargets addForwardOpaqueLate(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                    graph::ResourceHandle late) {
  auto& pass = graph.addPass("forward-opaque (late)", graph::QueueClass::Graphics);
  pass.read(targets.color, graph::Access::ColorAttachmentRead);
  pass.read(late, graph::Access::IndirectArgs);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  readFrameInputs(pass, view, view.draws);
  pass.execute([view, targets, late](PassContext& ctx) {
    ctx.beginRendering({ColorTarget{targets.color}}, DepthTarget{targets.depth}, true);
    render::SceneView lateView = view;
    lateView.indirect = ctx.buffer(late).handle();
    drawForward(ctx, lateView, drawsWithAlphaMode(view, scene::AlphaMode::Opaque), false);
    ctx.endRendering();
  });
  return targets;
}

}  // namespace sg::passes
