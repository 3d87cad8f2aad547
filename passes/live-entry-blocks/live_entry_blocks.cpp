#include "live_entry_blocks.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {
constexpr std::array kBindings{kBindOwnedEntries, kBindEntryBlocks, kBindObjectVisibility, kBindCulledDraws};
constexpr std::array kFrameBindings{kBindOwnedEntries, kBindEntryBlocks};  // bound from the frame
// dispatchEntrySpans' 32-entry workgroups: two per block, at most this many in x.
constexpr uint32_t kMaxBlocks = 65535 / 2;

uint32_t blocksOf(const SgEntrySpan& s) { return (s.end - s.begin + kEntryBlockSize - 1) / kEntryBlockSize; }
}  // namespace

uint32_t entryBlockCandidates(std::span<const SgEntrySpan> spans) {
  if (spans.size() > kMaxBlockSpans) return 0;
  uint64_t n = 0;
  for (const SgEntrySpan& s : spans) n += s.end > s.begin ? blocksOf(s) : 0;
  return n <= kMaxBlocks ? uint32_t(n) : 0;
}

gpu::ComputePipelineDesc liveEntryBlocksPipeline(bool header) {
  gpu::ComputePipelineDesc desc{.shader = {.path = "passes/live-entry-blocks/live_entry_blocks.comp"},
                                .layout = decoupledLayout(kBindings, false, header ? 0 : sizeof(SgEntryBlocksPush))};
  if (header) desc.shader.defines.push_back({"SG_BLOCKS_HEADER", "1"});
  return desc;
}

graph::ResourceHandle addLiveEntryBlocks(graph::RenderGraph& graph, DecoupledFrame& frame,
                                         const LiveEntryBlocksInput& input) {
  SgEntryBlocksPush push{};
  for (const SgEntrySpan& s : frame.liveSpans) {
    if (s.end <= s.begin) continue;
    push.spans[push.spanCount] = {s.begin, s.end, push.candidateBlocks};
    push.candidateBlocks += blocksOf(s);
    ++push.spanCount;
  }
  push.objectCount = frame.objectCount;
  push.parity = input.parity;
  push.historyValid = input.historyValid ? 1u : 0u;
  const render::DrawCommands* commands = frame.view.commands;
  const bool culled = commands && commands->handle.valid();
  push.culled = culled ? 1u : 0u;

  auto& pass = graph.addPass("live-entry-blocks", graph::QueueClass::Graphics, graph::PassKind::Compute);
  if (culled) pass.read(commands->handle, graph::Access::StorageRead);
  const graph::ResourceHandle visibility = pass.write(input.visibility, graph::Access::StorageReadWrite);
  frame.entryBlocks = graph.createBuffer(
      "live entry blocks", {.size = sizeof(SgEntryBlocksHeader) + sizeof(SgEntryBlock) * std::max(push.candidateBlocks, 1u)});
  frame.entryBlocks = pass.write(frame.entryBlocks, graph::Access::StorageReadWrite);
  pass.execute([push, frame, draws = culled ? commands->buffer : VK_NULL_HANDLE,
                visibilityBuffer = input.visibilityBuffer](PassContext& ctx) {
    const std::array writes{gpu::DescriptorWrite{kBindObjectVisibility, gpu::BufferBinding{visibilityBuffer}},
                            // Not read unless culled; something must be bound.
                            gpu::DescriptorWrite{kBindCulledDraws, gpu::BufferBinding{draws ? draws : visibilityBuffer}}};
    const auto& header = ctx.device().pipeline("live-entry-blocks-header", [] { return liveEntryBlocksPipeline(true); });
    bindDecoupled(ctx, header, frame, kFrameBindings, writes);
    vkCmdDispatch(ctx.cmd(), 1, 1, 1);
    gpu::memoryBarrier(ctx.cmd(), {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
                       {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT});
    const auto& pipeline = ctx.device().pipeline("live-entry-blocks", [] { return liveEntryBlocksPipeline(false); });
    bindDecoupled(ctx, pipeline, frame, kFrameBindings, writes);
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof push, &push);
    const uint32_t threads = std::max(push.candidateBlocks, push.objectCount);
    vkCmdDispatch(ctx.cmd(), (threads + 63) / 64, 1, 1);
  });
  return visibility;
}

}  // namespace sg::passes
