#include <shadelgraph/graph/cross_queue_order.hpp>

#include <algorithm>

namespace sg::graph {

void orderAcrossQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                       CrossQueueOrder& out) {
  out.batches.clear();
  for (auto& list : out.batchesOfQueue) list.clear();
  std::vector<uint32_t>& batchOf = out.batchOfPass;
  batchOf.assign(graph.passCount(), kInvalidIndex);
  for (uint32_t position = 0; position < order.size(); ++position) {
    const QueueClass queue = graph.pass(order[position]).queue;
    if (out.batches.empty() || out.batches.back().queue != queue) {
      out.batchesOfQueue[queueIndex(queue)].push_back(static_cast<uint32_t>(out.batches.size()));
      const auto value = static_cast<uint32_t>(out.batchesOfQueue[queueIndex(queue)].size());
      out.batches.push_back({.queue = queue, .firstPosition = position, .value = value});
    }
    batchOf[order[position].index] = static_cast<uint32_t>(out.batches.size() - 1);
  }
  for (const Dependency& e : deps.edges) {
    const uint32_t from = batchOf[e.from.index];
    const uint32_t to = batchOf[e.to.index];
    if (from == kInvalidIndex || to == kInvalidIndex) continue;
    const QueueClass producer = out.batches[from].queue;
    if (producer == out.batches[to].queue) continue;
    CrossQueueOrder::Wait& w = out.batches[to].waits[queueIndex(producer)];
    w.value = std::max(w.value, out.batches[from].value);
    w.stages |= any(e.dstStages) ? e.dstStages : PipelineStage::AllCommands;
  }
  for (const auto& list : out.batchesOfQueue) {
    std::array<uint32_t, kQueueClassCount> covered{};
    for (const uint32_t b : list) {
      for (uint32_t q = 0; q < kQueueClassCount; ++q) {
        covered[q] = std::max(covered[q], out.batches[b].waits[q].value);
        out.batches[b].waits[q].covered = covered[q];
      }
    }
  }
}

uint32_t CrossQueueOrder::availableFrom(uint32_t last, QueueMask used, QueueClass queue,
                                        PipelineStage& waitStages) const {
  const std::vector<uint32_t>& own = batchesOfQueue[queueIndex(queue)];
  // The first batch on `queue` that may run after `last`: the one holding
  // last + 1 or the next one (binary search by first position).
  auto first = std::upper_bound(own.begin(), own.end(), last,
                                [&](uint32_t position, uint32_t b) { return position < batches[b].firstPosition; });
  if (first != own.begin()) --first;  // the batch that may hold last + 1
  for (uint32_t q = 0; q < kQueueClassCount; ++q) {
    const auto other = static_cast<QueueClass>(q);
    if (other == queue || !any(used & toMask(other))) continue;
    // The value of `other`'s last batch at or before `last`.
    const std::vector<uint32_t>& theirs = batchesOfQueue[q];
    const auto after = std::upper_bound(theirs.begin(), theirs.end(), last,
                                        [&](uint32_t position, uint32_t b) { return position < batches[b].firstPosition; });
    const auto needed = static_cast<uint32_t>(after - theirs.begin());
    if (needed == 0) continue;  // not used there before `last`
    // The first batch on `queue` whose waits cover it (`covered` only grows).
    const auto proving = std::partition_point(own.begin(), own.end(),
                                              [&](uint32_t b) { return batches[b].waits[q].covered < needed; });
    if (proving == own.end()) return kInvalidIndex;
    // That batch waits for `needed` or more itself: its stages are the ones to chain with.
    waitStages |= batches[*proving].waits[q].stages;
    first = std::max(first, proving);
  }
  if (first == own.end()) return kInvalidIndex;
  return std::max(last + 1, batches[*first].firstPosition);
}

QueueClass CrossQueueOrder::queueAt(uint32_t position) const {
  const auto after = std::upper_bound(batches.begin(), batches.end(), position,
                                      [](uint32_t p, const Batch& b) { return p < b.firstPosition; });
  return std::prev(after)->queue;
}

}  // namespace sg::graph
