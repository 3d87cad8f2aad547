#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/render_graph.hpp>

#include <span>
#include <vector>

namespace sg::graph {

// One plan entry per declared resource: resolved description, union of usages,
// the queues that use it (concurrent when more than one), and its lifetime as
// positions in `order`. Only the passes in `order` count. Memory is placed later.
std::vector<PlannedResource> planResources(const RenderGraph& graph, std::span<const PassId> order,
                                           uint32_t outputWidth, uint32_t outputHeight);
// The same into `resources`, reusing its memory.
void planResources(const RenderGraph& graph, std::span<const PassId> order, uint32_t outputWidth,
                   uint32_t outputHeight, std::vector<PlannedResource>& resources);

}  // namespace sg::graph
