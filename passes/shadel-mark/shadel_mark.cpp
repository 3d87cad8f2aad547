#include "shadel_mark.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindFrame, kBindParams, kBindObjects, kBindShadelInstances, kBindLevelRects, kBindRemap};
}  // namespace

gpu::GraphicsPipelineDesc shadelMarkPipeline() {
  return {.vertex = {.path = "passes/shadel-mark/shadel_mark.vert"},
          .fragment = {.path = "passes/shadel-mark/shadel_mark.frag"},
          .layout = decoupledLayout(kBindings, false, sizeof(render::ObjectConstants)),
          .vertexInput = render::sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = false};
}

void addShadelMark(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle depth) {
  auto& pass = graph.addPass("shadel-mark", graph::QueueClass::Graphics);
  pass.read(depth, graph::Access::DepthRead);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
  pass.execute([frame, depth](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("shadel-mark", shadelMarkPipeline);
    ctx.beginRendering({}, DepthTarget{depth, {}, true}, true);
    bindDecoupled(ctx, pipeline, frame, kBindings);
    frame.view.scene.bindGeometry(ctx.cmd());
    const auto& draws = frame.view.scene.draws();
    for (size_t i = 0; i < frame.view.draws.size(); ++i)
      render::drawItem(ctx.cmd(), pipeline, draws[frame.view.draws[i]], frame.objectIds[i]);
    ctx.endRendering();
  });
}

}  // namespace sg::passes
