#include "support_expand.hpp"

#include <algorithm>
#include <array>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

constexpr std::array kBindings{kBindParams, kBindRemap,    kBindObjects, kBindShadelInstances,
                               kBindLevelRects, kBindOwnedEntries, kBindCounters, kBindSupportMasks,
                               kBindEntryBlocks};

const gpu::Pipeline& supportPipeline(PassContext& ctx, bool apply) {
  return ctx.device().pipeline(apply ? "support-expand-apply" : "support-expand-gather",
                               [&] { return supportExpandPipeline(apply); });
}

}  // namespace

gpu::ComputePipelineDesc supportExpandPipeline(bool apply) {
  gpu::ComputePipelineDesc desc{.shader = {.path = "passes/support-expand/support_expand.comp"},
                                .layout = decoupledLayout(kBindings, false, sizeof(SgEntrySpan))};
  if (apply) desc.shader.defines.push_back({"SG_SUPPORT_APPLY", "1"});
  return desc;
}

void addSupportExpand(graph::RenderGraph& graph, DecoupledFrame& frame) {
  // One 64-bit mask per owned entry, written by the gather dispatch, read by the apply one.
  auto masks = graph.createBuffer("support masks", {.size = 8ull * std::max(frame.ownedEntryCount, 1u)});
  auto& pass = graph.addPass("support-expand", graph::QueueClass::Graphics, graph::PassKind::Compute);
  frame.remap = pass.write(frame.remap, graph::Access::StorageReadWrite);
  frame.counters = pass.write(frame.counters, graph::Access::StorageReadWrite);
  masks = pass.write(masks, graph::Access::StorageReadWrite);
  readEntryBlocks(pass, frame);
  pass.execute([frame, masks](PassContext& ctx) {
    if (frame.liveSpans.empty()) return;
    const VkBuffer maskBuffer = ctx.buffer(masks).handle();
    const std::array extra{gpu::DescriptorWrite{kBindSupportMasks, gpu::BufferBinding{maskBuffer}}};

    const gpu::Pipeline& gather = supportPipeline(ctx, false);
    bindDecoupled(ctx, gather, frame, kBindings, extra);
    dispatchEntrySpans(ctx, gather, frame);  // a thread per live owned entry

    // Apply may start only when all of gather is done: apply reads the masks
    // gather wrote (a memory dependency), and writes occupancy gather read in
    // neighbouring entries (write-after-read: an execution dependency; without
    // it a chunk could grow from a chunk added in this very pass, a
    // nondeterministic cascade). The graph synchronizes only between passes.
    gpu::memoryBarrier(ctx.cmd(), {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});

    const gpu::Pipeline& apply = supportPipeline(ctx, true);
    bindDecoupled(ctx, apply, frame, kBindings, extra);
    dispatchEntrySpans(ctx, apply, frame);
  });
}

}  // namespace sg::passes
