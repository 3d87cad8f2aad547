#include "work_aggregate.hpp"

#include <array>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kOffsetBindings{kBindParams, kBindWork, kBindArgs};
constexpr std::array kFillBindings{kBindParams, kBindObjects,  kBindRemap,       kBindOwnedEntries,
                                   kBindWork,   kBindCounters, kBindShadeStamps, kBindChunkSlots,
                                   kBindEntryBlocks};
}  // namespace

gpu::ComputePipelineDesc workOffsetsPipeline() {
  return {.shader = {.path = "passes/work-aggregate/work_offsets.comp"}, .layout = decoupledLayout(kOffsetBindings)};
}

std::span<const uint32_t> workFillBindings() { return kFillBindings; }

gpu::ComputePipelineDesc workFillPipeline() {
  return {.shader = {.path = "passes/work-aggregate/work_fill.comp"},
          .layout = decoupledLayout(kFillBindings, false, sizeof(SgEntrySpan))};
}

void addWorkAggregate(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("work-aggregate", graph::QueueClass::AsyncCompute);
  pass.read(frame.remap, graph::Access::StorageRead);
  pass.read(frame.slots, graph::Access::StorageRead);
  if (frame.stamps.valid()) frame.stamps = pass.write(frame.stamps, graph::Access::StorageReadWrite);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);  // stale ages
  frame.work = pass.write(frame.work, graph::Access::StorageReadWrite);
  frame.args = pass.write(frame.args, graph::Access::StorageWrite);
  readEntryBlocks(pass, frame);
  pass.execute([frame](PassContext& ctx) {
    const auto& offsets = ctx.device().pipeline("work-offsets", workOffsetsPipeline);
    const auto& fill = ctx.device().pipeline("work-fill", workFillPipeline);
    bindDecoupled(ctx, offsets, frame, kOffsetBindings);
    vkCmdDispatch(ctx.cmd(), 1, 1, 1);
    // The fill step reads the offsets the first step wrote: a barrier inside the pass.
    gpu::memoryBarrier(ctx.cmd(), {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    bindDecoupled(ctx, fill, frame, kFillBindings);
    dispatchEntrySpans(ctx, fill, frame);
  });
}

}  // namespace sg::passes
