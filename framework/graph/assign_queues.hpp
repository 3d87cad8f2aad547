#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/render_graph.hpp>

#include <array>
#include <span>
#include <vector>

namespace sg::graph {

struct QueueSchedule {
  std::vector<Batch> batches;         // submission order; passes are ranges of the order given
  std::vector<SemaphoreWait> waits;   // grouped by batch
  std::vector<uint32_t> passBatch;    // per pass; kInvalidIndex for passes not in the order

  std::span<const SemaphoreWait> waitsOf(const Batch& batch) const { return slice(waits, batch.waits); }

  // assignQueues()'s working memory, kept so that the next call reuses it.
  struct Scratch {
    struct Need {
      uint64_t value = 0;
      PipelineStage stages = PipelineStage::None;
    };
    // Rows: 0 a spare, then batch + 1.
    std::vector<uint64_t> rowValue;  // the batch's value on its queue (the spare's 0)
    // The batches of each queue by value - 1, queue q's from q * (the order's size) on.
    std::vector<uint32_t> batchesOfQueue;
    // Per row and producing queue: the highest value needed and the stages that wait.
    std::vector<std::array<Need, kQueueClassCount>> needs;
    // Per waiting queue and producing queue: the waits so far, none covering
    // another (see WaitHistory): usually a few. A full array is rewritten as
    // one wait per stage bit, with the same coverage, so it never has to grow.
    struct Waits {
      static constexpr std::size_t kStageBits = 8 * sizeof(PipelineStage);
      std::array<Need, kStageBits> list;
      uint32_t count = 0;
    };
    std::array<std::array<Waits, kQueueClassCount>, kQueueClassCount> history;
  } scratch;
};

// Splits `order` into batches (consecutive passes on the same logical queue)
// and turns every dependency between batches on different queues into a
// timeline-semaphore wait on the producing batch's value (its 1-based index
// among its queue's batches). Waits are minimal: one per producing queue per
// batch (the highest value needed), and none where an earlier batch on the same
// queue already waited for at least that value at those stages (a wait also
// blocks every later submission on the queue). Chains through a third queue are
// not trusted: a signal only orders commands that ran in the waited stages.
// A batch signals only if somebody waits on it.
QueueSchedule assignQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                           std::span<const Dependency> handoffs = {});
// The same into `schedule`, reusing its memory.
void assignQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                  std::span<const Dependency> handoffs, QueueSchedule& schedule);

}  // namespace sg::graph
