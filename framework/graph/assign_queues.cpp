#include <shadelgraph/graph/assign_queues.hpp>

#include <algorithm>
#include <array>

namespace sg::graph {
namespace {

using Need = QueueSchedule::Scratch::Need;

// Stages already waited for on one queue for one producing queue: a wait on
// value v covers every value <= v, for its stages, for all later submissions.
// Waits another one covers are dropped, so the list stays a few entries long.
class WaitHistory {
 public:
  explicit WaitHistory(std::vector<Need>& waits) : waits_(waits) {}
  PipelineStage coveredStages(uint64_t value) const {
    PipelineStage stages = PipelineStage::None;
    for (const Need& w : waits_) {
      if (w.value >= value) stages |= w.stages;
    }
    return stages;
  }
  void add(Need wait) {
    std::erase_if(waits_, [&](const Need& w) { return w.value <= wait.value && contains(wait.stages, w.stages); });
    waits_.push_back(wait);
  }

 private:
  std::vector<Need>& waits_;
};

}  // namespace

QueueSchedule assignQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                           std::span<const Dependency> handoffs) {
  QueueSchedule schedule;
  assignQueues(graph, order, deps, handoffs, schedule);
  return schedule;
}

void assignQueues(const RenderGraph& graph, std::span<const PassId> order, const DependencyGraph& deps,
                  std::span<const Dependency> handoffs, QueueSchedule& schedule) {
  QueueSchedule::Scratch& scratch = schedule.scratch;
  schedule.batches.clear();
  schedule.waits.clear();
  schedule.batches.reserve(order.size());  // a batch per position at most
  schedule.waits.reserve(order.size());
  schedule.passBatch.assign(graph.passCount(), kInvalidIndex);
  // Rows of the tables below are batch + 1: row 0 is a spare (see require).
  std::vector<uint64_t>& rowValue = scratch.rowValue;
  rowValue.clear();
  rowValue.reserve(order.size() + 1);
  rowValue.push_back(0);
  for (std::vector<uint32_t>& ofQueue : scratch.batchesOfQueue) {
    ofQueue.clear();
    ofQueue.reserve(order.size());  // a batch per position at most
  }

  for (uint32_t position = 0; position < order.size(); ++position) {
    const PassId p = order[position];
    const QueueClass queue = graph.pass(p).queue;
    if (schedule.batches.empty() || schedule.batches.back().queue != queue) {
      auto& ofQueue = scratch.batchesOfQueue[queueIndex(queue)];
      ofQueue.push_back(static_cast<uint32_t>(schedule.batches.size()));
      rowValue.push_back(ofQueue.size());
      schedule.batches.push_back({.queue = queue, .passes = {position, 0}});
    }
    ++schedule.batches.back().passes.count;
    schedule.passBatch[p.index] = static_cast<uint32_t>(schedule.batches.size() - 1);
  }

  // Per batch and producing queue: the highest value needed and the stages
  // that wait. Edges that need no wait (one end culled, or both ends on one
  // queue: submission order and barriers suffice) update row 0, a spare
  // never read: no branch, as whether an edge crosses queues flips from edge
  // to edge. (A culled pass's kInvalidIndex + 1 wraps to row 0.)
  std::vector<std::array<Need, kQueueClassCount>>& needs = scratch.needs;
  needs.assign(schedule.batches.size() + 1, {});
  const auto require = [&](const Dependency& e) {
    const uint32_t fromRow = schedule.passBatch[e.from.index] + 1;
    const uint32_t toRow = schedule.passBatch[e.to.index] + 1;
    const QueueClass producer = graph.pass(e.from).queue;  // its batch's queue
    const bool waits = (fromRow != 0) & (producer != graph.pass(e.to).queue);
    Need& need = needs[toRow * waits][queueIndex(producer)];
    need.value = std::max(need.value, rowValue[fromRow]);
    // A wait blocking no stage would block nothing.
    need.stages |= any(e.dstStages) ? e.dstStages : PipelineStage::AllCommands;
  };
  for (const Dependency& e : deps.edges) require(e);
  for (const Dependency& e : handoffs) require(e);

  for (auto& ofWaiter : scratch.history) {
    for (std::vector<Need>& waits : ofWaiter) waits.clear();
  }
  for (uint32_t b = 0; b < schedule.batches.size(); ++b) {
    Batch& batch = schedule.batches[b];
    batch.waits.first = static_cast<uint32_t>(schedule.waits.size());
    for (uint32_t producer = 0; producer < kQueueClassCount; ++producer) {
      const Need& need = needs[b + 1][producer];
      if (need.value == 0) continue;
      WaitHistory waited(scratch.history[queueIndex(batch.queue)][producer]);
      const PipelineStage missing = need.stages & ~waited.coveredStages(need.value);
      if (!any(missing)) continue;
      schedule.waits.push_back({static_cast<QueueClass>(producer), need.value, missing});
      ++batch.waits.count;
      waited.add({need.value, missing});
      Batch& signaller = schedule.batches[scratch.batchesOfQueue[producer][need.value - 1]];
      signaller.signalValue = need.value;
    }
  }
}

}  // namespace sg::graph
