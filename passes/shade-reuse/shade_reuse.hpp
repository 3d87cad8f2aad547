#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Copies the chunks that keep last frame's shading (work-aggregate's reuse
// list) from frame.previousShaded into frame.shadedColor at their new
// addresses (async compute; before the layers shade the rest).
void addShadeReuse(graph::RenderGraph& graph, DecoupledFrame& frame);
gpu::ComputePipelineDesc shadeReusePipeline();

}  // namespace sg::passes
