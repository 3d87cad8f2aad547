#include "alpha_blend.hpp"

#include <algorithm>

#include "forward/forward_material.hpp"

namespace sg::passes {

graph::ResourceHandle addAlphaBlend(graph::RenderGraph& graph, const render::SceneView& view,
                                    const glm::vec3& cameraPosition, ForwardTargets targets) {
  auto& pass = graph.addPass("alpha-blend", graph::QueueClass::Graphics);
  pass.read(targets.color, graph::Access::ColorAttachmentRead);  // blends over the opaque result
  pass.read(targets.depth, graph::Access::DepthRead);
  targets.color = pass.write(targets.color, graph::Access::ColorAttachment);
  readFrameInputs(pass, view, view.draws);
  render::readSceneGeometry(pass, view);
  pass.execute([view = render::readDrawCommands(pass, view), targets, cameraPosition](PassContext& ctx) {
    // Back to front by the distance of each object's origin: the usual
    // compromise for per-object sorting (intersecting objects stay wrong).
    const auto& draws = view.scene.draws();
    std::vector<uint32_t> order;
    for (uint32_t d : view.draws)
      if (draws[d].alphaMode == scene::AlphaMode::Blend) order.push_back(d);
    auto distance = [&](uint32_t d) { return glm::distance(glm::vec3(draws[d].world[3]), cameraPosition); };
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return distance(a) > distance(b); });
    ctx.beginRendering({ColorTarget{targets.color}}, DepthTarget{targets.depth, {}, true}, true);
    drawForward(ctx, view, order, true);
    ctx.endRendering();
  });
  return targets.color;
}

}  // namespace sg::passes
