#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>

namespace sg::passes {

// Draws the decoupled objects with their shaded samples (manual trilinear
// through the remap table) over the forward pass's colour. Returns the colour.
graph::ResourceHandle addComposite(graph::RenderGraph& graph, render::DecoupledFrame& frame, graph::ResourceHandle color,
                                   graph::ResourceHandle depth);

}  // namespace sg::passes
