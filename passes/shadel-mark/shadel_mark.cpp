#include "shadel_mark.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

void addShadelMark(graph::RenderGraph& graph, render::DecoupledFrame& frame, graph::ResourceHandle depth) {
  auto& pass = graph.addPass("shadel-mark", graph::QueueClass::Graphics);
  pass.read(depth, graph::Access::DepthRead);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite, graph::ShaderStage::Fragment);
  pass.execute([frame, depth](PassContext& ctx) {
    using namespace render;
    const std::array bindings{kBindFrame, kBindParams, kBindObjects, kBindShadelInstances, kBindLevelRects, kBindRemap};
    const auto& pipeline = ctx.device().pipeline("shadel-mark", [&] {
      return gpu::GraphicsPipelineDesc{
          .vertex = {.path = "passes/shadel-mark/shadel_mark.vert"},
          .fragment = {.path = "passes/shadel-mark/shadel_mark.frag"},
          .layout = decoupledLayout(bindings,
                                    false, sizeof(ObjectConstants)),
          .vertexInput = sceneVertexInput(),
          .depthFormat = VK_FORMAT_D32_SFLOAT,
          .depthTest = true,
          .depthWrite = false};
    });
    ctx.beginRendering({}, DepthTarget{depth, {}, true}, true);
    bindDecoupled(ctx, pipeline, frame, bindings);
    frame.view.scene.bindGeometry(ctx.cmd());
    const auto& draws = frame.view.scene.draws();
    for (size_t i = 0; i < frame.view.draws.size(); ++i)
      drawItem(ctx.cmd(), pipeline, draws[frame.view.draws[i]], frame.objectIds[i]);
    ctx.endRendering();
  });
}

}  // namespace sg::passes
