#include <shadelgraph/graph/assign_queues.hpp>

#include <algorithm>
#include <array>
#include <span>

namespace sg::graph {
namespace {

using Need = QueueSchedule::Scratch::Need;

// Stages already waited for on one queue for one producing queue: a wait on
// value v covers every value <= v, for its stages, for all later submissions.
// Waits another one covers are dropped, so the list stays a few entries long.
class WaitHistory {
 public:
  explicit WaitHistory(QueueSchedule::Scratch::Waits& waits) : waits_(waits) {}
  PipelineStage coveredStages(uint64_t value) const {
    PipelineStage stages = PipelineStage::None;
    for (const Need& w : waits()) {
      if (w.value >= value) stages |= w.stages;
    }
    return stages;
  }
  void add(Need wait) {
    Need* const first = waits_.list.data();
    Need* const end = std::remove_if(first, first + waits_.count, [&](const Need& w) {
      return w.value <= wait.value && contains(wait.stages, w.stages);
    });
    if (end == first + waits_.list.size()) [[unlikely]] return addPerStage(wait);
    *end = wait;
    waits_.count = static_cast<uint32_t>(end - first) + 1;
  }

 private:
  // The array full (rare: it holds a wait per stage bit): the same coverage
  // as one wait per stage, at the highest value waited for there.
  [[gnu::noinline]] void addPerStage(Need wait) {
    std::array<uint64_t, QueueSchedule::Scratch::Waits::kStageBits> highest{};
    const auto raise = [&](const Need& w) {
      for (uint32_t b = 0; b < highest.size(); ++b) {
        if ((static_cast<uint32_t>(w.stages) >> b) & 1u) highest[b] = std::max(highest[b], w.value);
      }
    };
    for (const Need& w : waits()) raise(w);
    raise(wait);
    waits_.count = 0;
    for (uint32_t b = 0; b < highest.size(); ++b) {
      if (highest[b] != 0) waits_.list[waits_.count++] = {highest[b], static_cast<PipelineStage>(1u << b)};
    }
  }

  std::span<Need> waits() const { return {waits_.list.data(), waits_.count}; }
  QueueSchedule::Scratch::Waits& waits_;
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
  // A batch per position at most, on any queue.
  const std::size_t stride = order.size();
  if (scratch.batchesOfQueue.size() < kQueueClassCount * stride) scratch.batchesOfQueue.resize(kQueueClassCount * stride);
  std::array<uint32_t, kQueueClassCount> batchCount{};

  for (uint32_t position = 0; position < order.size(); ++position) {
    const PassId p = order[position];
    const QueueClass queue = graph.pass(p).queue;
    if (schedule.batches.empty() || schedule.batches.back().queue != queue) {
      uint32_t& count = batchCount[queueIndex(queue)];
      scratch.batchesOfQueue[queueIndex(queue) * stride + count++] = static_cast<uint32_t>(schedule.batches.size());
      rowValue.push_back(count);
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
    for (QueueSchedule::Scratch::Waits& waits : ofWaiter) waits.count = 0;
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
      Batch& signaller = schedule.batches[scratch.batchesOfQueue[producer * stride + need.value - 1]];
      signaller.signalValue = need.value;
    }
  }
}

}  // namespace sg::graph
