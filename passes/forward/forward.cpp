#include "forward.hpp"

#include "forward_material.hpp"

namespace sg::passes {

ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                glm::vec3 background) {
  auto& pass = graph.addPass("forward-opaque", graph::QueueClass::Graphics);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  pass.read(targets.depth, graph::Access::DepthRead);
  readFrameInputs(pass, view, view.draws);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), targets, background](PassContext& ctx) {
    ctx.beginRendering({ColorTarget{targets.color, VkClearColorValue{{background.r, background.g, background.b, 1.0f}}}},
                       DepthTarget{targets.depth, {}, true}, true);
    drawForward(ctx, view, drawsWithAlphaMode(view, scene::AlphaMode::Opaque), false);
    ctx.endRendering();
  });
  return targets;
}

}  // namespace sg::passes
