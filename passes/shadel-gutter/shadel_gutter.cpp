#include "shadel_gutter.hpp"

#include <algorithm>
#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindShadelInstances, kBindLevelRects, kBindRemap, kBindOwnedEntries,
                               kBindChunkSlots, kBindLayerImage, kBindEntryBlocks};
}  // namespace

gpu::ComputePipelineDesc shadelGutterPipeline() {
  return {.shader = {.path = "passes/shadel-gutter/shadel_gutter.comp"},
          .layout = decoupledLayout(kBindings, /*layerImageStorage*/ true, sizeof(SgEntrySpan))};
}

void addShadelGutter(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-gutter", graph::QueueClass::AsyncCompute);
  pass.read(frame.remap, graph::Access::StorageRead);
  pass.read(frame.slots, graph::Access::StorageRead);
  frame.shadedColor = pass.write(frame.shadedColor, graph::Access::StorageReadWrite);
  readEntryBlocks(pass, frame);
  pass.execute([frame](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("shadel-gutter", shadelGutterPipeline);
    bindDecoupled(ctx, pipeline, frame, kBindings);
    dispatchEntrySpans(ctx, pipeline, frame, 32);  // 32 owned entries each (the shader's kEntriesPerGroup)
  });
}

}  // namespace sg::passes
