#include "shadel_allocate.hpp"

#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindObjects, kBindRemap, kBindOwnedEntries, kBindCounters, kBindWork,
                               kBindPreviousRemap, kBindPreviousStamps};
}  // namespace

gpu::ComputePipelineDesc shadelAllocatePipeline() {
  return {.shader = {.path = "passes/shadel-allocate/shadel_allocate.comp"}, .layout = decoupledLayout(kBindings)};
}

void addShadelAllocate(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-allocate", graph::QueueClass::AsyncCompute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite);
  if (frame.previousRemap.valid()) pass.read(frame.previousRemap, graph::Access::StorageRead);
  if (frame.previousStamps.valid()) pass.read(frame.previousStamps, graph::Access::StorageRead);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);
  frame.work = pass.write(frame.work, graph::Access::StorageReadWrite);
  pass.execute([frame](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("shadel-allocate", shadelAllocatePipeline);
    bindDecoupled(ctx, pipeline, frame, kBindings);
    if (frame.ownedEntryCount) vkCmdDispatch(ctx.cmd(), (frame.ownedEntryCount + 63) / 64, 1, 1);
  });
}

}  // namespace sg::passes
