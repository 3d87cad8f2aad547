#include <shadelgraph/graph/plan_resources.hpp>

namespace sg::graph {

std::vector<PlannedResource> planResources(const RenderGraph& graph, std::span<const PassId> order,
                                           uint32_t outputWidth, uint32_t outputHeight) {
  std::vector<PlannedResource> resources;
  planResources(graph, order, outputWidth, outputHeight, resources);
  return resources;
}

void planResources(const RenderGraph& graph, std::span<const PassId> order, uint32_t outputWidth,
                   uint32_t outputHeight, std::vector<PlannedResource>& resources) {
  resources.resize(graph.resourceCount());
  for (uint32_t r = 0; r < graph.resourceCount(); ++r) {
    const ResourceDecl& decl = graph.resource(ResourceId{r});
    PlannedResource& out = resources[r];
    std::string name = std::move(out.name);  // keep the string's buffer for the assignment below
    out = PlannedResource{};
    out.name = std::move(name);
    out.name = decl.name;
    out.kind = decl.kind;
    out.desc.type = decl.type;
    if (decl.type == ResourceType::Image) {
      out.desc.image = resolveImageDesc(decl.image, outputWidth, outputHeight);
    } else {
      out.desc.bufferSize = decl.buffer.size;
    }
    out.initialState = decl.initialState;
    out.finalState = decl.finalState;
    out.readOnly = decl.readOnly;
    out.historyOf = decl.historyOf;
    out.culled = true;
  }

  for (uint32_t position = 0; position < order.size(); ++position) {
    const PassDecl& pass = graph.pass(order[position]);
    for (const ResourceAccess& a : graph.accessesOf(order[position])) {
      PlannedResource& r = resources[a.resource.index];
      if (r.culled) {
        r.culled = false;
        r.firstUse = position;
      }
      r.lastUse = position;
      r.desc.queues |= toMask(pass.queue);
      r.desc.imageUsage |= imageUsageOf(a.access);
      r.desc.bufferUsage |= bufferUsageOf(a.access);
    }
  }
  for (PlannedResource& r : resources) {
    if (r.desc.type == ResourceType::Image) r.desc.bufferUsage = BufferUsage::None;
    else r.desc.imageUsage = ImageUsage::None;
    // Resources shared between queues use concurrent sharing, so no queue-family
    // ownership transfer is ever needed (see docs: simpler, and lavapipe has a
    // single family anyway; forgotten ownership transfers are a classic bug).
    r.desc.concurrent = queueCount(r.desc.queues) > 1;
  }
}

}  // namespace sg::graph
