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
  struct Wait {
    uint32_t value = 0;  // highest value of the producing queue this batch itself waits for (0: none)
    PipelineStage stages = PipelineStage::None;
    uint32_t covered = 0;  // highest value waited for by this batch or an earlier one on its queue
  };
  struct Batch {
    QueueClass queue = QueueClass::Graphics;
    uint32_t firstPosition = 0;
    uint32_t value = 0;  // its 1-based index among its queue's batches
    std::array<Wait, kQueueClassCount> waits{};  // by producing queue
  };
  std::vector<Batch> batches;                                          // as assignQueues() splits the order
  std::array<std::vector<uint32_t>, kQueueClassCount> batchesOfQueue;  // by value - 1
  std::vector<uint32_t> batchOfPass;                                   // kInvalidIndex if not in the order

  // The first position in the order from which a pass on `queue` runs after
  // every command up to position `last` on the queues in `used`: right after
  // `last` if `used` has no other queue, else from the first batch on `queue`
  // that waited for each other queue's batch at or before `last` (kInvalidIndex
  // if none does). `waitStages` gets the stages of those waits: a barrier
  // chaining with them needs them in its source.
  uint32_t availableFrom(uint32_t last, QueueMask used, QueueClass queue, PipelineStage& waitStages) const;
  // The queue of the pass at `position`.
  QueueClass queueAt(uint32_t position) const;
};

// Batches of `order` and their waits for the dependencies of `deps`, the way
// assignQueues() makes them: its waits (which also serve the layout hand-offs
// planBarriers() adds) always cover these.
void orderAcrossQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                       CrossQueueOrder& out);

}  // namespace sg::graph
