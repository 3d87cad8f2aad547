#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Resets the owned remap entries, the shade counters and the per-object work
// counts (compute, on the graphics queue: shadel-mark follows).
void addShadelClear(graph::RenderGraph& graph, DecoupledFrame& frame);
// entries: the remap-entry reset over a live span (SG_CLEAR_ENTRIES, pushes SgEntrySpan); else the counters.
gpu::ComputePipelineDesc shadelClearPipeline(bool entries);

}  // namespace sg::passes
