#include <shadelgraph/graph/cross_queue_order.hpp>

#include <shadelgraph/graph/branchless.hpp>

#include <algorithm>
#include <bit>

namespace sg::graph {

void orderAcrossQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                       CrossQueueOrder& out) {
  // Whether a pass starts a batch, and whether an edge crosses queues, flip at
  // random from one to the next: both loops write unconditionally (a batch
  // per position at most, rewritten until its last pass; edges that need no
  // wait update a spare batch past the last) instead of branching.
  out.batches.resize(order.size() + 1);
  out.batchAt.resize(order.size());
  uint32_t count = 0;  // batches so far
  const uint32_t spare = static_cast<uint32_t>(order.size());
  out.batchOfPass.assign(graph.passCount(), spare);  // culled passes: the spare
  std::array<uint32_t, kQueueClassCount> submitted{};
  for (uint32_t position = 0; position < order.size(); ++position) {
    const QueueClass queue = graph.pass(order[position]).queue;
    const bool starts = count == 0 || out.batches[count - 1].queue != queue;
    count += starts;
    submitted[queueIndex(queue)] += starts;
    CrossQueueOrder::Batch& batch = out.batches[count - 1];
    batch = {.queue = queue, .firstPosition = choose(starts, position, batch.firstPosition), .submitted = submitted};
    out.batchAt[position] = count - 1;
    out.batchOfPass[order[position].index] = count - 1;
  }
  out.batches[spare] = {};
  for (const Dependency& e : deps.edges) {
    const uint32_t from = out.batchOfPass[e.from.index];
    const uint32_t to = out.batchOfPass[e.to.index];
    const uint32_t producer = queueIndex(out.batches[from].queue);
    const bool waits = (from != spare) & (to != spare) & (producer != queueIndex(out.batches[to].queue));
    CrossQueueOrder::Batch& waiter = out.batches[choose(waits, to, spare)];
    // A batch's value: its 1-based index among its queue's batches.
    waiter.waitValue[producer] = std::max(waiter.waitValue[producer], out.batches[from].submitted[producer]);
    waiter.waitStages[producer] |= any(e.dstStages) ? e.dstStages : PipelineStage::AllCommands;
  }
  out.batches.resize(count);
  uint32_t covers = 0;
  for (uint32_t waiting = 0; waiting < kQueueClassCount; ++waiting) {
    for (uint32_t producer = 0; producer < kQueueClassCount; ++producer) {
      out.firstCoverAt[waiting][producer] = covers;
      covers += submitted[producer];
    }
  }
  out.firstCover.assign(covers, kInvalidIndex);
  std::array<std::array<uint32_t, kQueueClassCount>, kQueueClassCount> covered{};  // [waiting][producer]
  for (uint32_t b = 0; b < out.batches.size(); ++b) {
    const CrossQueueOrder::Batch& batch = out.batches[b];
    const uint32_t waiting = queueIndex(batch.queue);
    for (uint32_t producer = 0; producer < kQueueClassCount; ++producer) {
      uint32_t* firstCover = out.firstCover.data() + out.firstCoverAt[waiting][producer];
      for (uint32_t& c = covered[waiting][producer]; c < batch.waitValue[producer]; ++c) firstCover[c] = b;
    }
  }
}

uint32_t CrossQueueOrder::availableFrom(uint32_t last, QueueMask used, QueueClass queue,
                                        PipelineStage& waitStages) const {
  uint32_t position = last + 1;
  const uint32_t waiting = queueIndex(queue);
  // Only the other queues in `used` (each bit of the mask is a queue index).
  auto others = static_cast<uint32_t>(used & ~toMask(queue)) & ((1u << kQueueClassCount) - 1);
  if (others == 0) return position;
  const Batch& lastBatch = batches[batchAt[last]];
  for (; others != 0; others &= others - 1) {
    const auto producer = static_cast<uint32_t>(std::countr_zero(others));
    // The value of the producer's last batch at or before `last`.
    const uint32_t needed = lastBatch.submitted[producer];
    if (needed == 0) continue;  // not used there before `last`
    const uint32_t proving = firstCover[firstCoverAt[waiting][producer] + needed - 1];
    if (proving == kInvalidIndex) return kInvalidIndex;
    // That batch waits for `needed` or more itself: its stages are the ones to chain with.
    waitStages |= batches[proving].waitStages[producer];
    position = std::max(position, batches[proving].firstPosition);
  }
  return position;
}

}  // namespace sg::graph
