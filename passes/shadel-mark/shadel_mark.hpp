#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Rasterizes the decoupled objects against the z-prepass depth (early test,
// no colour; unless the depth pre-pass wrote frame.markRequests, below) and
// marks the chunks of the shadels composite will read with frame.filter
// (recorded in frame.markedFilter). With frame.shadelMasks it
// creates frame.masks, zeroed by a transfer pass (shadel-mask-clear) first,
// and marks in them which shadels of each chunk composite reads
// (with markOwnChunkOnly, the neighbours' part in a compute pass after it).
void addShadelMark(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle depth);
// With shadel masks and the bilinear or trilinear filter, the fragment shader
// marks only the mask of each footprint's own chunk, and a compute pass after
// it (shadel-mark-neighbours) adds what the marked chunks' gutters read to
// their neighbours' masks (shadel_mark_neighbours.comp); the point filter's
// single tap may lie in the gutter, so there the fragment shader marks the
// neighbour itself, as before.
bool markOwnChunkOnly(int filter, bool shadelMasks);
// Marking in the depth pre-pass: where markRequestsPossible (shadel masks,
// the bilinear filter: one footprint a pixel), the depth pre-pass draws the
// decoupled objects itself with drawMarkRequests (render::DepthPassDraws):
// their fragment shader writes each pixel's mask slot and box to an R32UI
// target (frame.markRequests) instead of setting mask bits with an atomic,
// so the objects are rasterized once less. addShadelMark then adds a compute
// pass (shadel-mark-requests) that sets the bits, one atomic per distinct
// slot of each 4x4 pixels. A request holds the slot in 26 bits: fewer than
// kMaxRequestEntries owned entries.
constexpr uint32_t kMaxRequestEntries = 1u << 20;
bool markRequestsPossible(const DecoupledFrame& frame);
void drawMarkRequests(PassContext& ctx, const DecoupledFrame& frame, VkBuffer indirect);
gpu::ComputePipelineDesc shadelMarkNeighboursPipeline();
gpu::ComputePipelineDesc shadelMarkRequestsPipeline();
// filter: 0 point, 1 bilinear, 2 trilinear (what composite filters with);
// baseline: the mark before issue 14 (bench --baseline); alphaTest: the
// variant for alpha-mask objects, `materialSet` (the scene material) its set 1;
// shadelMasks: also the shadel masks (DecoupledFrame::shadelMasks);
// levelRule: the variant for objects with that level rule
// (shadel::packLevelRule; 0 none), which composite must be compiled with too.
gpu::GraphicsPipelineDesc shadelMarkPipeline(int filter, bool baseline = false, bool alphaTest = false,
                                             VkDescriptorSetLayout materialSet = VK_NULL_HANDLE,
                                             bool shadelMasks = false, uint32_t levelRule = 0, bool requests = false);

}  // namespace sg::passes
