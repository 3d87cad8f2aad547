#include <shadelgraph/graph/plan_resources.hpp>

namespace sg::graph {

// One walk over the kept passes' accesses, in order: lifetimes, usages, queues.
void gatherUsage(const RenderGraph& graph, std::span<const PassId> order, std::vector<ResourceUsage>& usage) {
  usage.assign(graph.resourceCount(), ResourceUsage{});
  for (uint32_t position = 0; position < order.size(); ++position) {
    const QueueMask queue = toMask(graph.pass(order[position]).queue);
    for (const ResourceAccess& a : graph.accessesOf(order[position])) {
      ResourceUsage& u = usage[a.resource.index];
      if (u.firstUse == kInvalidIndex) u.firstUse = position;
      u.lastUse = position;
      u.queues |= queue;
      u.imageUsage |= imageUsageOf(a.access);
      u.bufferUsage |= bufferUsageOf(a.access);
    }
  }
}

void planResource(const ResourceDecl& decl, const ResourceUsage& usage, uint32_t outputWidth, uint32_t outputHeight,
                  PlannedResource& out) {
  std::string name = std::move(out.name);  // keep the string's buffer for the assignment below
  out = PlannedResource{};
  out.name = std::move(name);
  out.name = decl.name;
  out.kind = decl.kind;
  out.culled = usage.firstUse == kInvalidIndex;
  out.readOnly = decl.readOnly;
  out.historyOf = decl.historyOf;
  out.firstUse = usage.firstUse;
  out.lastUse = usage.lastUse;
  out.desc.type = decl.type;
  if (decl.type == ResourceType::Image) {
    out.desc.image = resolveImageDesc(decl.image, outputWidth, outputHeight);
    out.desc.imageUsage = usage.imageUsage;
  } else {
    out.desc.bufferSize = decl.buffer.size;
    out.desc.bufferUsage = usage.bufferUsage;
  }
  out.desc.queues = usage.queues;
  // Resources shared between queues use concurrent sharing, so no queue-family
  // ownership transfer is ever needed (see docs: simpler, and lavapipe has a
  // single family anyway; forgotten ownership transfers are a classic bug).
  out.desc.concurrent = queueCount(usage.queues) > 1;
  out.initialState = decl.initialState;
  out.finalState = decl.finalState;
}

std::vector<PlannedResource> planResources(const RenderGraph& graph, std::span<const PassId> order,
                                           uint32_t outputWidth, uint32_t outputHeight) {
  std::vector<PlannedResource> resources;
  planResources(graph, order, outputWidth, outputHeight, resources);
  return resources;
}

void planResources(const RenderGraph& graph, std::span<const PassId> order, uint32_t outputWidth,
                   uint32_t outputHeight, std::vector<PlannedResource>& resources) {
  // The scattered per-access updates go to the small usage array; then each
  // plan entry is written once, in one sequential sweep.
  std::vector<ResourceUsage> usage;
  gatherUsage(graph, order, usage);
  resources.resize(graph.resourceCount());
  for (uint32_t r = 0; r < graph.resourceCount(); ++r) {
    planResource(graph.resource(ResourceId{r}), usage[r], outputWidth, outputHeight, resources[r]);
  }
}

}  // namespace sg::graph
