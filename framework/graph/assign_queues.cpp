#include <shadelgraph/graph/assign_queues.hpp>

#include <algorithm>
#include <array>

namespace sg::graph {
namespace {

struct Need {
  uint64_t value = 0;
  PipelineStage stages = PipelineStage::None;
};

// Stages already waited for on one queue for one producing queue: a wait on
// value v covers every value <= v, for its stages, for all later submissions.
// Waits another one covers are dropped, so the list stays a few entries long.
class WaitHistory {
 public:
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
  std::vector<Need> waits_;
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
  schedule.batches.clear();
  schedule.waits.clear();
  schedule.batches.reserve(order.size());  // a batch per position at most
  schedule.waits.reserve(order.size());
  schedule.passBatch.assign(graph.passCount(), kInvalidIndex);
  // Sized once (a batch per position at most) instead of regrown batch by batch.
  std::vector<uint64_t> batchValue;
  batchValue.reserve(order.size());
  std::array<std::vector<uint32_t>, kQueueClassCount> batchesOfQueue;  // by value - 1

  for (uint32_t position = 0; position < order.size(); ++position) {
    const PassId p = order[position];
    const QueueClass queue = graph.pass(p).queue;
    if (schedule.batches.empty() || schedule.batches.back().queue != queue) {
      auto& ofQueue = batchesOfQueue[queueIndex(queue)];
      if (ofQueue.empty()) ofQueue.reserve(order.size() - position);
      ofQueue.push_back(static_cast<uint32_t>(schedule.batches.size()));
      batchValue.push_back(ofQueue.size());
      schedule.batches.push_back({.queue = queue, .passes = {position, 0}});
    }
    ++schedule.batches.back().passes.count;
    schedule.passBatch[p.index] = static_cast<uint32_t>(schedule.batches.size() - 1);
  }

  // Per batch and producing queue: the highest value needed and the stages that wait.
  std::vector<std::array<Need, kQueueClassCount>> needs(schedule.batches.size());
  const auto require = [&](const Dependency& e) {
    const uint32_t from = schedule.passBatch[e.from.index];
    const uint32_t to = schedule.passBatch[e.to.index];
    if (from == kInvalidIndex || to == kInvalidIndex) return;
    const QueueClass producer = schedule.batches[from].queue;
    if (producer == schedule.batches[to].queue) return;  // submission order and barriers suffice
    Need& need = needs[to][queueIndex(producer)];
    need.value = std::max(need.value, batchValue[from]);
    // A wait blocking no stage would block nothing.
    need.stages |= any(e.dstStages) ? e.dstStages : PipelineStage::AllCommands;
  };
  for (const Dependency& e : deps.edges) require(e);
  for (const Dependency& e : handoffs) require(e);

  std::array<std::array<WaitHistory, kQueueClassCount>, kQueueClassCount> history;  // [waiting queue][producer]
  for (uint32_t b = 0; b < schedule.batches.size(); ++b) {
    Batch& batch = schedule.batches[b];
    batch.waits.first = static_cast<uint32_t>(schedule.waits.size());
    for (uint32_t producer = 0; producer < kQueueClassCount; ++producer) {
      const Need& need = needs[b][producer];
      if (need.value == 0) continue;
      WaitHistory& waited = history[queueIndex(batch.queue)][producer];
      const PipelineStage missing = need.stages & ~waited.coveredStages(need.value);
      if (!any(missing)) continue;
      schedule.waits.push_back({static_cast<QueueClass>(producer), need.value, missing});
      ++batch.waits.count;
      waited.add({need.value, missing});
      Batch& signaller = schedule.batches[batchesOfQueue[producer][need.value - 1]];
      signaller.signalValue = need.value;
    }
  }
}

}  // namespace sg::graph
