#include "forward.hpp"

#include <shadelgraph/render/frame_uniforms.hpp>

#include "forward_material.hpp"

namespace sg::passes {

glm::vec3 hdrBackground(std::span<const scene::Light> lights) {
  return glm::vec3(0.42f, 0.55f, 0.75f) * render::skyScale(lights);
}

std::optional<VkClearColorValue> clearIfUnwritten(graph::ResourceHandle color, glm::vec3 background) {
  if (color.version != 0) return std::nullopt;
  return VkClearColorValue{{background.r, background.g, background.b, 1.0f}};
}

ForwardTargets addForwardOpaque(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                glm::vec3 background, OverdrawCounter counter) {
  const bool writesDepth = targets.depth.version == 0;  // no z-prepass drew it
  auto& pass = graph.addPass("forward-opaque", graph::QueueClass::Graphics);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  if (writesDepth)
    targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  else
    pass.read(targets.depth, graph::Access::DepthRead);
  readFrameInputs(pass, view, view.draws);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), targets, background, writesDepth,
                counter](PassContext& ctx) {
    const DepthTarget depth = writesDepth ? DepthTarget{targets.depth, 1.0f} : DepthTarget{targets.depth, {}, true};
    ctx.beginRendering({ColorTarget{targets.color, VkClearColorValue{{background.r, background.g, background.b, 1.0f}}}},
                       depth, true);
    drawForward(ctx, view, drawsWithAlphaMode(view, scene::AlphaMode::Opaque), false, counter);
    ctx.endRendering();
  });
  return targets;
}

ForwardTargets addForwardOpaqueLate(graph::RenderGraph& graph, const render::SceneView& view, ForwardTargets targets,
                                    graph::ResourceHandle late) {
  auto& pass = graph.addPass("forward-opaque (late)", graph::QueueClass::Graphics);
  pass.read(late, graph::Access::IndirectArgs);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  targets.depth = pass.write(targets.depth, graph::Access::DepthAttachment);
  readFrameInputs(pass, view, view.draws);
  render::readSceneGeometry(pass, view);
  pass.execute([view, targets, late](PassContext& ctx) {
    render::SceneView lateView = view;
    lateView.indirect = ctx.buffer(late).handle();
    ctx.beginRendering({ColorTarget{targets.color, {}}}, DepthTarget{targets.depth, {}}, true);
    drawForward(ctx, lateView, drawsWithAlphaMode(lateView, scene::AlphaMode::Opaque), false);
    ctx.endRendering();
  });
  return targets;
}

}  // namespace sg::passes
