#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Stable allocation (async compute): chunks still marked keep their storage,
// those no longer marked free theirs, newly marked ones take free chunks;
// overflow counted; the chunks that keep their shading counted apart.
void addShadelAllocate(graph::RenderGraph& graph, DecoupledFrame& frame);
// Its steps: 1 frees, 2 allocates (the host resets the slots: ChunkSlots).
gpu::ComputePipelineDesc shadelAllocatePipeline(int phase = 2);

}  // namespace sg::passes
