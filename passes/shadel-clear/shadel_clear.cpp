#include "shadel_clear.hpp"

#include <algorithm>
#include <array>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindRemap, kBindOwnedEntries, kBindCounters, kBindWork};
}  // namespace

gpu::ComputePipelineDesc shadelClearPipeline() {
  return {.shader = {.path = "passes/shadel-clear/shadel_clear.comp"}, .layout = decoupledLayout(kBindings)};
}

void addShadelClear(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-clear", graph::QueueClass::Graphics, graph::PassKind::Compute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageWrite);
  frame.counters = pass.write(frame.counters, graph::Access::StorageWrite);
  frame.work = pass.write(frame.work, graph::Access::StorageWrite);
  pass.execute([frame](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("shadel-clear", shadelClearPipeline);
    bindDecoupled(ctx, pipeline, frame, kBindings);
    const uint32_t n = std::max({frame.ownedEntryCount, frame.objectCount, 64u});
    vkCmdDispatch(ctx.cmd(), (n + 63) / 64, 1, 1);
  });
}

}  // namespace sg::passes
