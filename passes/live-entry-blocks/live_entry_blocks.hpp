#pragma once
// live-entry-blocks: which blocks of 64 owned entries the per-entry passes
// visit this frame, decided on the GPU from the occlusion cull. The live spans
// (objects shaded now or last frame, sg::shadel::liveEntrySpans) without the
// objects the cull hid this frame and last frame; their indirect dispatch
// arguments (passes::dispatchEntrySpans reads them when the frame has blocks).
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>

#include <decoupled_frame.hpp>

namespace sg::passes {

struct LiveEntryBlocksInput {
  // Per decoupled object, its visibility in the two frame parities (persistent, 8 bytes per object).
  graph::ResourceHandle visibility;
  VkBuffer visibilityBuffer = VK_NULL_HANDLE;
  uint32_t parity = 0;        // this frame's half
  bool historyValid = false;  // the other half holds last frame's (else every object counts as seen last frame)
};

// Candidate blocks of the spans (each span cut in blocks of kEntryBlockSize); 0 when they are more
// than the blocks' dispatches can take (dispatchEntrySpans then dispatches the spans).
uint32_t entryBlockCandidates(std::span<const SgEntrySpan> spans);

// Declares the pass; sets frame.entryBlocks. The spans must have candidates (entryBlockCandidates).
// Returns the visibility buffer's new version.
graph::ResourceHandle addLiveEntryBlocks(graph::RenderGraph& graph, DecoupledFrame& frame,
                                         const LiveEntryBlocksInput& input);
// The pass's two steps: the header (indirect arguments of no block), then the blocks.
gpu::ComputePipelineDesc liveEntryBlocksPipeline(bool header);

}  // namespace sg::passes
