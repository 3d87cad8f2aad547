#include "shadel_allocate.hpp"

#include <array>
#include <string>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kFreeBindings{kBindParams, kBindRemap, kBindOwnedEntries, kBindChunkSlots, kBindEntryBlocks};
constexpr std::array kTakeBindings{kBindParams, kBindObjects, kBindRemap,       kBindOwnedEntries,
                                   kBindCounters, kBindWork,   kBindChunkSlots, kBindShadeStamps,
                                   kBindEntryBlocks};

std::span<const uint32_t> phaseBindings(int phase) {
  if (phase == 1) return kFreeBindings;
  return kTakeBindings;
}

// Each step reads what the one before wrote.
void computeToCompute(VkCommandBuffer cmd) {
  gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                     {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
}
}  // namespace

gpu::ComputePipelineDesc shadelAllocatePipeline(int phase) {
  return {.shader = {.path = "passes/shadel-allocate/shadel_allocate.comp",
                     .defines = {{"SG_PHASE", std::to_string(phase)}}},
          .layout = decoupledLayout(phaseBindings(phase), false, sizeof(SgEntrySpan))};
}

void addShadelAllocate(graph::RenderGraph& graph, DecoupledFrame& frame) {
  auto& pass = graph.addPass("shadel-allocate", graph::QueueClass::AsyncCompute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite);
  frame.slots = pass.write(frame.slots, graph::Access::StorageReadWrite);
  if (frame.stamps.valid()) pass.read(frame.stamps, graph::Access::StorageRead);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);
  frame.work = pass.write(frame.work, graph::Access::StorageReadWrite);
  readEntryBlocks(pass, frame);
  pass.execute([frame](PassContext& ctx) {
    if (frame.liveSpans.empty()) return;
    const auto& release = ctx.device().pipeline("shadel-allocate-free", [] { return shadelAllocatePipeline(1); });
    bindDecoupled(ctx, release, frame, kFreeBindings);
    dispatchEntrySpans(ctx, release, frame);
    computeToCompute(ctx.cmd());
    const auto& take = ctx.device().pipeline("shadel-allocate", [] { return shadelAllocatePipeline(2); });
    bindDecoupled(ctx, take, frame, kTakeBindings);
    dispatchEntrySpans(ctx, take, frame);
  });
}

}  // namespace sg::passes
