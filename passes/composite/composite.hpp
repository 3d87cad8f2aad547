#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// Draws the decoupled objects with their shaded samples (manual trilinear
// through the remap table) over the forward pass's colour. Returns the colour.
graph::ResourceHandle addComposite(graph::RenderGraph& graph, DecoupledFrame& frame, graph::ResourceHandle color,
                                   graph::ResourceHandle depth);
// filter: 0 point, 1 bilinear, 2 trilinear; levelView shows the detail level instead.
gpu::GraphicsPipelineDesc compositePipeline(int filter, bool levelView);

}  // namespace sg::passes
