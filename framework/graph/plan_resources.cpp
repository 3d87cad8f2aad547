#include <shadelgraph/graph/plan_resources.hpp>

#include <algorithm>

namespace sg::graph {

// One walk over the kept passes' accesses, in order: lifetimes, usages, queues.
void gatherUsage(const RenderGraph& graph, std::span<const PassId> order, std::vector<ResourceUsage>& usage) {
  usage.assign(graph.resourceCount(), ResourceUsage{});
  for (uint32_t position = 0; position < order.size(); ++position) {
    const QueueMask queue = toMask(graph.pass(order[position]).queue);
    for (const ResourceAccess& a : graph.accessesOf(order[position])) {
      ResourceUsage& u = usage[a.resource.index];
      u.firstUse = std::min(u.firstUse, position);  // kInvalidIndex until the first; no branch on "first?"
      u.lastUse = position;
      u.queues |= queue;
      u.imageUsage |= imageUsageOf(a.access);
      u.bufferUsage |= bufferUsageOf(a.access);
    }
  }
}

void planResource(const ResourceDecl& decl, const ResourceUsage& usage, uint32_t outputWidth, uint32_t outputHeight,
                  PlannedResource& out) {
  // Every field written once, in place (no whole-struct temporary): the entry
  // is reused frame after frame, and its name keeps its buffer.
  out.name = decl.name;
  out.kind = decl.kind;
  out.culled = usage.firstUse == kInvalidIndex;
  out.readOnly = decl.readOnly;
  out.historyOf = decl.historyOf;
  out.firstUse = usage.firstUse;
  out.lastUse = usage.lastUse;
  out.aliasesWith = {};
  out.memory = {};
  out.requirements = {};
  ResourceDesc& desc = out.desc;
  desc.type = decl.type;
  if (decl.type == ResourceType::Image) {
    desc.image = resolveImageDesc(decl.image, outputWidth, outputHeight);
    desc.bufferSize = 0;
    desc.imageUsage = usage.imageUsage;
    desc.bufferUsage = BufferUsage::None;
  } else {
    desc.image = {};
    desc.bufferSize = decl.buffer.size;
    desc.imageUsage = ImageUsage::None;
    desc.bufferUsage = usage.bufferUsage;
  }
  desc.queues = usage.queues;
  // Resources shared between queues use concurrent sharing, so no queue-family
  // ownership transfer is ever needed (see docs: simpler, and lavapipe has a
  // single family anyway; forgotten ownership transfers are a classic bug).
  desc.concurrent = queueCount(usage.queues) > 1;
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
