#include "shade_frame_work.hpp"

#include <array>
#include <string>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

#include "work-aggregate/work_aggregate.hpp"

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindParams, kBindRemap, kBindOwnedEntries, kBindWork, kBindChunkSlots, kBindEntryBlocks};
constexpr std::array kOffsetBindings{kBindParams, kBindWork, kBindArgs};

// Each step reads (and adds to) what the one before wrote.
void computeToCompute(VkCommandBuffer cmd) {
  gpu::memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                     {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
}
}  // namespace

gpu::ComputePipelineDesc shadeFramePhasePipeline(int phase) {
  return {.shader = {.path = "passes/shade-frame/shade_frame_work.comp", .defines = {{"SG_PHASE", std::to_string(phase)}}},
          .layout = decoupledLayout(kBindings, false, phase == 0 ? 0 : sizeof(SgEntrySpan))};
}

gpu::ComputePipelineDesc shadeFrameFillPipeline() {
  auto desc = workFillPipeline();
  desc.shader.defines.push_back({"SG_SHADE_ALL", "1"});
  return desc;
}

void addShadeFrameWork(graph::RenderGraph& graph, DecoupledFrame& shadeFrame) {
  auto& pass = graph.addPass("shade-frame-work", graph::QueueClass::AsyncCompute);
  pass.read(shadeFrame.remap, graph::Access::StorageRead);
  pass.read(shadeFrame.slots, graph::Access::StorageRead);
  shadeFrame.work = pass.write(shadeFrame.work, graph::Access::StorageReadWrite);
  shadeFrame.args = pass.write(shadeFrame.args, graph::Access::StorageWrite);
  // The fill step stamps every chunk with this frame (it is all shaded now) and may count ages.
  if (shadeFrame.stamps.valid()) shadeFrame.stamps = pass.write(shadeFrame.stamps, graph::Access::StorageReadWrite);
  shadeFrame.counters = pass.write(shadeFrame.counters, graph::Access::StorageReadWrite);
  readEntryBlocks(pass, shadeFrame);
  pass.execute([frame = shadeFrame](PassContext& ctx) {
    const auto& clear = ctx.device().pipeline("shade-frame-clear", [] { return shadeFramePhasePipeline(0); });
    const auto& count = ctx.device().pipeline("shade-frame-count", [] { return shadeFramePhasePipeline(1); });
    const auto& offsets = ctx.device().pipeline("work-offsets", workOffsetsPipeline);
    const auto& fill = ctx.device().pipeline("work-fill-all", shadeFrameFillPipeline);
    const uint32_t slots = kWorkSlotsPerObject * frame.objectCount + kWorkGlobalSlots;
    bindDecoupled(ctx, clear, frame, kBindings);
    vkCmdDispatch(ctx.cmd(), (slots + 63) / 64, 1, 1);
    computeToCompute(ctx.cmd());
    bindDecoupled(ctx, count, frame, kBindings);
    dispatchEntrySpans(ctx, count, frame);
    computeToCompute(ctx.cmd());
    bindDecoupled(ctx, offsets, frame, kOffsetBindings);
    vkCmdDispatch(ctx.cmd(), 1, 1, 1);
    computeToCompute(ctx.cmd());
    bindDecoupled(ctx, fill, frame, workFillBindings());
    dispatchEntrySpans(ctx, fill, frame);
  });
}

}  // namespace sg::passes
