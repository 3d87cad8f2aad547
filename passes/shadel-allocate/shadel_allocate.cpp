#include "shadel_allocate.hpp"

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {

void addShadelAllocate(graph::RenderGraph& graph, render::DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-allocate", graph::QueueClass::AsyncCompute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);
  frame.work = pass.write(frame.work, graph::Access::StorageReadWrite);
  pass.execute([frame](PassContext& ctx) {
    using namespace render;
    const auto& pipeline = ctx.device().pipeline("shadel-allocate", [] {
      return gpu::ComputePipelineDesc{
          .shader = {.path = "passes/shadel-allocate/shadel_allocate.comp"},
          .layout = decoupledLayout({kBindParams, kBindRemap, kBindOwnedEntries, kBindCounters, kBindWork})};
    });
    bindDecoupled(ctx, pipeline, frame, {kBindParams, kBindRemap, kBindOwnedEntries, kBindCounters, kBindWork});
    if (frame.ownedEntryCount) vkCmdDispatch(ctx.cmd(), (frame.ownedEntryCount + 63) / 64, 1, 1);
  });
}

}  // namespace sg::passes
