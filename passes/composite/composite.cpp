#include "composite.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include <shadelgraph/gpu/pass_context.hpp>

#include "shadel-gutter/shadel_gutter.hpp"

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindFrame, kBindParams, kBindObjects,  kBindShadelInstances,
                               kBindLevelRects, kBindRemap, kBindChunkSlots, kBindCounters, kBindLayerImage};
}  // namespace

gpu::GraphicsPipelineDesc compositePipeline(int filter, bool levelView) {
  std::vector<std::pair<std::string, std::string>> defines{filterDefine(filter)};
  if (levelView) defines.emplace_back("SG_VIEW_LEVEL", "1");
  return {.vertex = {.path = "passes/composite/composite.vert"},
          .fragment = {.path = "passes/composite/composite.frag", .defines = defines},
          .layout = decoupledLayout(kBindings, false, sizeof(render::ObjectConstants)),
          .vertexInput = render::sceneVertexInput(),
          .colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT},
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = false};
}

graph::ResourceHandle addComposite(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle color,
                                   graph::ResourceHandle depth) {
  // Composite reads exactly the footprint shadel-mark marked for its filter:
  // any other filter would read unmarked shadels (misses).
  if (frame.markedFilter >= 0 && frame.markedFilter != frame.filter)
    throw std::logic_error("composite filter " + std::to_string(frame.filter) + " differs from shadel-mark's " +
                           std::to_string(frame.markedFilter));
  // Each level's footprint is read from one chunk tile: fill the tiles' gutters first.
  addShadelGutter(graph, frame);
  auto& pass = graph.addPass("composite", graph::QueueClass::Graphics);
  pass.read(color, graph::Access::ColorAttachmentRead);
  pass.read(depth, graph::Access::DepthRead);
  pass.read(frame.remap, graph::Access::StorageRead);
  pass.read(frame.slots, graph::Access::StorageRead);
  pass.read(frame.shadedColor, graph::Access::Sampled);
  render::readSceneGeometry(pass, frame.view);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);  // misses
  color = pass.write(color, graph::Access::ColorAttachment);
  // Culled draws (instance count 0 in the frame's draw commands) are skipped.
  pass.execute([indirect = render::readDrawCommands(pass, frame.view).indirect, frame, color, depth](PassContext& ctx) {
    const std::string variant = std::to_string(frame.filter) + (frame.levelView ? "/level" : "");
    const auto& pipeline =
        ctx.device().pipeline("composite/" + variant, [&] { return compositePipeline(frame.filter, frame.levelView); });
    ctx.beginRendering({ColorTarget{color}}, DepthTarget{depth, {}, true}, true);
    bindDecoupled(ctx, pipeline, frame, kBindings);
    frame.view.scene.bindGeometry(ctx.cmd());
    const auto& draws = frame.view.scene.draws();
    for (size_t i = 0; i < frame.view.draws.size(); ++i)
      render::drawItem(ctx.cmd(), pipeline, draws[frame.view.draws[i]], frame.objectIds[i], indirect,
                       frame.view.draws[i]);
    ctx.endRendering();
  });
  return color;
}

}  // namespace sg::passes
