#include "shadel_mark.hpp"

#include <array>
#include <string>
#include <vector>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindFrame, kBindParams, kBindObjects, kBindShadelInstances, kBindLevelRects, kBindRemap};
}  // namespace

gpu::GraphicsPipelineDesc shadelMarkPipeline(int filter, bool baseline) {
  std::vector<std::pair<std::string, std::string>> defines{filterDefine(filter)};
  if (baseline) defines.emplace_back("SG_MARK_BASELINE", "1");
  return {.vertex = {.path = "passes/shadel-mark/shadel_mark.vert"},
          .fragment = {.path = "passes/shadel-mark/shadel_mark.frag", .defines = defines},
          .layout = decoupledLayout(kBindings, false, sizeof(render::ObjectConstants)),
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = false};
}

void addShadelMark(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle depth) {
  auto& pass = graph.addPass("shadel-mark", graph::QueueClass::Graphics);
  pass.read(depth, graph::Access::DepthRead);
  render::readSceneGeometry(pass, frame.view);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
  frame.markedFilter = frame.filter;
  // Culled draws (instance count 0 in the frame's draw commands) are skipped.
  pass.execute([indirect = render::readDrawCommands(pass, frame.view).indirect, frame, depth](PassContext& ctx) {
    const std::string variant = std::to_string(frame.filter) + (frame.baseline ? "/baseline" : "");
    const auto& pipeline = ctx.device().pipeline(
        "shadel-mark/" + variant, [&] { return shadelMarkPipeline(frame.filter, frame.baseline); });
    ctx.beginRendering({}, DepthTarget{depth, {}, true}, true);
    bindDecoupled(ctx, pipeline, frame, kBindings);
    frame.view.scene.bindGeometry(ctx.cmd());
    const auto& draws = frame.view.scene.draws();
    for (size_t i = 0; i < frame.view.draws.size(); ++i)
      render::drawItem(ctx.cmd(), pipeline, draws[frame.view.draws[i]], frame.objectIds[i], indirect,
                       frame.view.draws[i]);
    ctx.endRendering();
  });
}

}  // namespace sg::passes
