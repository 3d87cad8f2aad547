#include <shadelgraph/graph/frame_boundary.hpp>

#include <algorithm>
#include <array>

namespace sg::graph {
namespace {

bool isExternal(ResourceKind kind) { return !isTransient(kind); }

}  // namespace

void neededByResults(const RenderGraph& graph, const VersionTable& versions, const DependencyGraph& deps,
                     std::span<const PassId> order, std::vector<bool>& needed) {
  const GraphDeclaration& declared = graph.declaration();
  // Roots, then (backwards over the order, as dependencies point forwards)
  // every pass a needed pass depends on.
  needed.assign(graph.passCount(), false);
  for (const ResourceHandle output : declared.outputs) {
    const PassId producer = versions.producerOf(output.id, output.version);
    if (producer.valid()) needed[producer.index] = true;
  }
  for (const PassId p : order) {
    if (graph.pass(p).sideEffect || (versions.passKinds[p.index].accessed & kindBit(ResourceKind::Imported)) != 0) {
      needed[p.index] = true;
    }
  }
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    if (needed[it->index]) continue;
    for (const Dependency& e : deps.successors(*it))
      if (needed[e.to.index]) {
        needed[it->index] = true;
        break;
      }
  }
}

void orderTailLast(const std::vector<bool>& needed, std::vector<PassId>& order) {
  bool seenTail = false, needsMove = false;
  for (const PassId p : order) {
    seenTail = seenTail || !needed[p.index];
    needsMove = needsMove || (seenTail && needed[p.index]);
  }
  // Needed passes never depend on the others: both runs keep a valid order.
  if (needsMove) std::stable_partition(order.begin(), order.end(), [&](PassId p) { return bool(needed[p.index]); });
}

void planFrameBoundary(const RenderGraph& graph, const VersionTable& versions, const std::vector<bool>& needed,
                       std::span<const uint32_t> passBatch, CompiledPlan& plan) {
  const GraphDeclaration& declared = graph.declaration();

  plan.hostWaitBatch.fill(kInvalidIndex);
  for (const PassId p : plan.order)
    if (needed[p.index]) plan.hostWaitBatch[queueIndex(graph.pass(p).queue)] = passBatch[p.index];
  for (uint32_t b = 0; b < plan.batches.size(); ++b) {
    Batch& batch = plan.batches[b];
    const uint32_t last = plan.hostWaitBatch[queueIndex(batch.queue)];
    batch.tail = last == kInvalidIndex || b > last;
  }

  // External resources: first and last batch per queue, in resource order.
  // A frame has few (imports, persistent and history resources): an entry
  // per external resource and queue, in plan.externalUses itself (found by
  // binary search; no table per resource, nothing allocated once the plan's
  // array has room), then the unused entries dropped.
  std::vector<ExternalUse>& uses = plan.externalUses;
  uses.clear();
  uses.reserve(kQueueClassCount * static_cast<std::size_t>(std::count_if(
                                      declared.traits.begin(), declared.traits.end(),
                                      [](const ResourceTraits& t) { return isExternal(t.kind); })));
  for (uint32_t r = 0; r < declared.traits.size(); ++r) {
    if (!isExternal(declared.traits[r].kind)) continue;
    for (uint32_t q = 0; q < kQueueClassCount; ++q) uses.push_back({.resource = ResourceId{r}, .queue = static_cast<QueueClass>(q)});
  }
  if (uses.empty()) return;
  for (const PassId p : plan.order) {
    if ((versions.passKinds[p.index].accessed & kExternalKinds) == 0) continue;
    const QueueClass queue = graph.pass(p).queue;
    const uint32_t batch = passBatch[p.index];
    for (const ResourceAccess& a : graph.accessesOf(p)) {
      if (!isExternal(declared.traits[a.resource.index].kind)) continue;
      const auto first = std::lower_bound(uses.begin(), uses.end(), a.resource,
                                          [](const ExternalUse& u, ResourceId r) { return u.resource < r; });
      ExternalUse& use = first[queueIndex(queue)];
      if (use.firstBatch == kInvalidIndex) {
        use = {a.resource, queue, batch, batch, a.stages};
      } else if (use.firstBatch == batch) {
        use.firstStages |= a.stages;
      }
      use.lastBatch = batch;
    }
  }
  std::erase_if(uses, [](const ExternalUse& use) { return use.firstBatch == kInvalidIndex; });
}

}  // namespace sg::graph
