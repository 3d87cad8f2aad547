#pragma once
// What the submission order and the cross-queue semaphore waits prove about
// when work on one logical queue is over for another: placement aliases
// transients across queues only where this proves their lifetimes disjoint.

#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/queue.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/graph/sync_types.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sg::graph {

struct CrossQueueOrder {
  struct Batch {
    QueueClass queue = QueueClass::Graphics;
    uint32_t firstPosition = 0;
    // Per producing queue: the highest value this batch itself waits for (0: none), at which stages.
    std::array<uint32_t, kQueueClassCount> waitValue{};
    std::array<PipelineStage, kQueueClassCount> waitStages{};
    // Per queue: how many of its batches were submitted up to this one (included).
    std::array<uint32_t, kQueueClassCount> submitted{};
  };
  std::vector<Batch> batches;         // as assignQueues() splits the order
  std::vector<uint32_t> batchAt;      // per position in the order
  std::vector<uint32_t> batchOfPass;  // per pass; the order's size if not in it
  // Per waiting queue, producing queue and value: the first batch on the
  // waiting queue that waited for at least that value (kInvalidIndex: none),
  // at firstCover[firstCoverAt[waiting][producer] + value - 1] (one array for
  // all pairs of queues: one allocation instead of one per pair).
  std::vector<uint32_t> firstCover;
  std::array<std::array<uint32_t, kQueueClassCount>, kQueueClassCount> firstCoverAt{};

  // The first position in the order from which a pass on `queue` runs after
  // every command up to position `last` on the queues in `used`: right after
  // `last` if `used` has no other queue, else from the first batch on `queue`
  // that waited for each other queue's batch at or before `last` (kInvalidIndex
  // if none does). `waitStages` gets the stages of those waits: a barrier
  // chaining with them needs them in its source. O(1).
  uint32_t availableFrom(uint32_t last, QueueMask used, QueueClass queue, PipelineStage& waitStages) const;
  QueueClass queueAt(uint32_t position) const { return batches[batchAt[position]].queue; }
};

// Batches of `order` and their waits for the dependencies of `deps`, the way
// assignQueues() makes them: its waits (which also serve the layout hand-offs
// planBarriers() adds) always cover these.
void orderAcrossQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                       CrossQueueOrder& out);

}  // namespace sg::graph
