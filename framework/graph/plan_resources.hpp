#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/render_graph.hpp>

#include <span>
#include <vector>

namespace sg::graph {

// How the kept passes use one resource, gathered in one walk over their
// accesses. Kept apart from the (large) PlannedResource so that the walk's
// scattered updates touch a small, cache-resident array.
struct ResourceUsage {
  uint32_t firstUse = kInvalidIndex;  // positions in the order
  QueueMask queues = QueueMask::None;
  ImageUsage imageUsage = ImageUsage::None;
  BufferUsage bufferUsage = BufferUsage::None;
  uint32_t lastUse = kInvalidIndex;
};

// One plan entry per declared resource: resolved description, union of usages,
// the queues that use it (concurrent when more than one), and its lifetime as
// positions in `order`. Only the passes in `order` count. Memory is placed later.
std::vector<PlannedResource> planResources(const RenderGraph& graph, std::span<const PassId> order,
                                           uint32_t outputWidth, uint32_t outputHeight);
// The same into `resources`, reusing its memory.
void planResources(const RenderGraph& graph, std::span<const PassId> order, uint32_t outputWidth,
                   uint32_t outputHeight, std::vector<PlannedResource>& resources);
// The two halves of planResources(), for callers that do more per resource in
// the same sweep (PlanCompiler gathers memory requirements there): the usage
// of every resource by the passes in `order`, then one resource's plan entry.
void gatherUsage(const RenderGraph& graph, std::span<const PassId> order, std::vector<ResourceUsage>& usage);
void planResource(const ResourceDecl& decl, const ResourceUsage& usage, uint32_t outputWidth, uint32_t outputHeight,
                  PlannedResource& out);

}  // namespace sg::graph
