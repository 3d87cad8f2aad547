#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>

namespace sg::passes {

// Storage for every marked chunk, from hashed partitions; overflow counted (async compute).
void addShadelAllocate(graph::RenderGraph& graph, render::DecoupledFrame& frame);

}  // namespace sg::passes
