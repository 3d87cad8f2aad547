#pragma once
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/decoupled_frame.hpp>

namespace sg::passes {

// Per-object work lists in one shared buffer and one VkDispatchIndirectCommand
// per object per material layer (async compute).
void addWorkAggregate(graph::RenderGraph& graph, render::DecoupledFrame& frame);

}  // namespace sg::passes
