#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Marks the chunks around the marked ones for objects whose layers read
// neighbours (DecoupledObject::supportChunks > 0), inside each level rectangle,
// and counts them in ShadeCounters::supportChunks. Between shadel-mark and
// shadel-allocate (compute, on the graphics queue). Twin of shadel::expandSupport.
void addSupportExpand(graph::RenderGraph& graph, DecoupledFrame& frame);
// The shader's gather half, or with `apply` its apply half.
gpu::ComputePipelineDesc supportExpandPipeline(bool apply);

}  // namespace sg::passes
