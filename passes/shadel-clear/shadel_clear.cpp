#include "shadel_clear.hpp"

#include <algorithm>
#include <array>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindRemap, kBindOwnedEntries, kBindCounters, kBindWork, kBindEntryBlocks};
}  // namespace

gpu::ComputePipelineDesc shadelClearPipeline(bool entries) {
  gpu::ComputePipelineDesc desc{.shader = {.path = "passes/shadel-clear/shadel_clear.comp"},
                                .layout = decoupledLayout(kBindings, false, entries ? sizeof(SgEntrySpan) : 0)};
  if (entries) desc.shader.defines.push_back({"SG_CLEAR_ENTRIES", "1"});
  return desc;
}

void addShadelClear(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-clear", graph::QueueClass::Graphics, graph::PassKind::Compute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageWrite);
  frame.counters = pass.write(frame.counters, graph::Access::StorageWrite);
  frame.work = pass.write(frame.work, graph::Access::StorageWrite);
  readEntryBlocks(pass, frame);
  pass.execute([frame](PassContext& ctx) {
    const auto& counters = ctx.device().pipeline("shadel-clear", [] { return shadelClearPipeline(false); });
    bindDecoupled(ctx, counters, frame, kBindings);
    const uint32_t n = std::max(frame.objectCount, 64u);
    vkCmdDispatch(ctx.cmd(), (n + 63) / 64, 1, 1);
    // The remap entries of the live span only; it counts the entries it visits in the counters just cleared.
    gpu::memoryBarrier(ctx.cmd(), {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    const auto& entries = ctx.device().pipeline("shadel-clear-entries", [] { return shadelClearPipeline(true); });
    bindDecoupled(ctx, entries, frame, kBindings);
    dispatchEntrySpans(ctx, entries, frame);
  });
}

}  // namespace sg::passes
