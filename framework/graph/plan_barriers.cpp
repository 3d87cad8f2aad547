#include <shadelgraph/graph/plan_barriers.hpp>

#include <shadelgraph/graph/branchless.hpp>

#include <algorithm>
#include <array>

namespace sg::graph {
namespace {

using Use = ResourceUse;

// `flags` if `keep`, else none: a multiply by 0 or 1 instead of a branch, where
// `keep` flips from one resource or use to the next (fewer instructions than a
// mask made of the 16-bit flags).
template <BitmaskEnum Flags>
constexpr Flags keptIf(bool keep, Flags flags) {
  using Bits = std::underlying_type_t<Flags>;
  return static_cast<Flags>(static_cast<uint32_t>(static_cast<Bits>(flags)) * static_cast<uint32_t>(keep));
}

// Uses grouped by resource, each group in execution order (views of the scratch).
struct UseTable {
  const std::vector<uint32_t>& first;    // per resource, plus one
  const std::vector<uint32_t>& lastUse;  // per resource: position in the order of its last use
  const std::vector<Use>& uses;

  std::span<const Use> of(uint32_t r) const { return {uses.data() + first[r], uses.data() + first[r + 1]}; }
};

UseTable collectUses(const RenderGraph& graph, std::span<const PassId> order, uint32_t resourceCount,
                     BarrierPlan::Scratch& scratch) {
  // One walk over the kept passes appends each pass's uses in execution order
  // (a pass's accesses to one resource merged) and counts them per resource;
  // a counting sort then groups them by resource. (The sort's flat loop has
  // one exit; a second walk over the passes would pay every pass's inner-loop
  // exit again.)
  std::vector<uint32_t>& first = scratch.firstUse;
  std::vector<uint32_t>& lastUse = scratch.lastUse;
  std::vector<Use>& uses = scratch.uses;
  std::vector<BarrierPlan::Scratch::UseInOrder>& inOrder = scratch.inOrder;
  first.assign(resourceCount + 1, 0);
  lastUse.assign(resourceCount, kInvalidIndex);
  // Every stage and write of each resource, on the way: what a transient taking over its memory waits for.
  std::vector<BarrierPlan::Scratch::Footprint>& footprints = scratch.footprints;
  footprints.assign(resourceCount, {});
  inOrder.resize(graph.declaration().accesses.size());  // at most one use per access
  BarrierPlan::Scratch::UseInOrder* next = inOrder.data();
  for (uint32_t position = 0; position < order.size(); ++position) {
    const PassId p = order[position];
    const QueueClass queue = graph.pass(p).queue;
    for (const ResourceAccess& a : graph.accessesOf(p)) {
      const uint32_t r = a.resource.index;
      BarrierPlan::Scratch::Footprint& footprint = footprints[r];
      footprint.stages |= a.stages;
      footprint.writes |= writeBits(a.accessFlags);
      if (lastUse[r] == position) [[unlikely]] {
        // A second access of the pass to this resource: merge it into the pass's use, a few entries back.
        BarrierPlan::Scratch::UseInOrder* earlier = next - 1;
        while (earlier->resource != r) --earlier;
        Use& use = earlier->use;
        use.stages |= a.stages;
        use.access |= a.accessFlags;
        use.write = use.write || a.write;
        if (const auto merged = mergeLayouts(use.layout, a.layout)) use.layout = *merged;
        continue;
      }
      lastUse[r] = position;
      ++first[r + 1];
      *next++ = {r, {p, queue, a.stages, a.accessFlags, a.layout, a.write}};
    }
  }
  for (uint32_t r = 0; r < resourceCount; ++r) first[r + 1] += first[r];
  uses.resize(first[resourceCount]);
  std::vector<uint32_t>& cursor = scratch.cursor;
  cursor.assign(first.begin(), first.end() - 1);
  for (const BarrierPlan::Scratch::UseInOrder* u = inOrder.data(); u != next; ++u) uses[cursor[u->resource]++] = u->use;
  return {first, lastUse, uses};
}

using TakeOver = BarrierPlan::Scratch::TakeOver;

// Adds to `takeOver` one alias of its resource: only earlier occupants count,
// not later ones (masks: which it is flips at random).
void addAlias(TakeOver& takeOver, bool earlier, const BarrierPlan::Scratch::Footprint& previous) {
  takeOver.aliased |= earlier;
  takeOver.stages |= keptIf(earlier, previous.stages);
  takeOver.writes |= keptIf(earlier, previous.writes);
}

// Per resource, what taking over aliased memory waits for (last uses from the
// use table: a small array, where alias lists point anywhere).
const std::vector<TakeOver>& findTakeOvers(std::span<const PlannedResource> resources,
                                           std::span<const ResourceId> aliases, const std::vector<uint32_t>& lastUse,
                                           const std::vector<BarrierPlan::Scratch::Footprint>& footprints,
                                           BarrierPlan::Scratch& scratch) {
  const auto resourceCount = static_cast<uint32_t>(resources.size());
  const auto aliasCount = static_cast<uint32_t>(aliases.size());
  std::vector<TakeOver>& takeOvers = scratch.takeOvers;
  takeOvers.assign(resourceCount, {});
  // One flat walk over every alias, not a loop per resource, whose exit (after
  // 0 to a few aliases) was mispredicted about once a resource. With the lists
  // back to back in resource order (as placeTransients lays them out), an
  // alias belongs to the resource numbered by how many lists ended at or before it.
  std::vector<uint32_t>& endsAt = scratch.aliasListEnds;
  endsAt.assign(aliasCount + 1, 0);
  uint32_t end = 0;
  bool backToBack = true;
  for (const PlannedResource& resource : resources) {
    backToBack &= resource.aliasesWith.first == end;
    end = resource.aliasesWith.first + resource.aliasesWith.count;
    ++endsAt[std::min(end, aliasCount)];
  }
  if (backToBack & (end == aliasCount)) {
    uint32_t owner = 0;
    for (uint32_t i = 0; i < aliasCount; ++i) {
      owner += endsAt[i];
      const uint32_t other = aliases[i].index;
      addAlias(takeOvers[owner], lastUse[other] < resources[owner].firstUse, footprints[other]);
    }
    return takeOvers;
  }
  for (uint32_t r = 0; r < resourceCount; ++r) {
    for (const ResourceId other : aliases.subspan(resources[r].aliasesWith.first, resources[r].aliasesWith.count))
      addAlias(takeOvers[r], lastUse[other.index] < resources[r].firstUse, footprints[other.index]);
  }
  return takeOvers;
}

// Barriers as they are found (resource by resource), before grouping by pass;
// final barriers and hand-offs straight into the plan.
struct EmittedBarriers {
  using Entry = BarrierPlan::Scratch::Entry;
  Entry* next;  // into the scratch's entries, room for one per use
  std::vector<FinalBarrier>& finals;
  std::vector<Dependency>& handoffs;

  void add(PassId pass, bool after, const Barrier& b) { *next++ = {pass.index * 2 + (after ? 1u : 0u), b}; }
};

// What a queue already guarantees about the current version of a resource.
// (16 bytes, not 9: indexing by queue is a shift, and resetting all three
// after a write three 16-byte copies.)
struct alignas(16) QueueSync {
  PipelineStage waitStages = PipelineStage::None;  // reads and barrier destinations a later write/transition waits for
  PipelineStage visibleStages = PipelineStage::None;
  AccessFlag visibleAccess = AccessFlag::None;
  bool allVisible = false;    // the last write arrived through a semaphore
  bool writeChained = false;  // a barrier here already waited for the last write; later ones chain through waitStages
  bool transitioned = false;  // the layout changed here since the last write
};

// What each queue knows right after a write on queue w: nothing on w, and all
// of it on the others (they get it through semaphores). One copy per write.
using QueueSyncs = std::array<QueueSync, kQueueClassCount>;
constexpr std::array<QueueSyncs, kQueueClassCount> kAfterWriteOn = [] {
  std::array<QueueSyncs, kQueueClassCount> table{};
  for (uint32_t w = 0; w < kQueueClassCount; ++w)
    for (uint32_t q = 0; q < kQueueClassCount; ++q) table[w][q].allVisible = q != w;
  return table;
}();

// Walks one resource's uses and emits its barriers. Most resources are used
// on one queue (kSeveralQueues false): their planner keeps one queue's state
// and skips what only sharing between queues needs (runs of reads on several
// queues, prior work on other queues, hand-offs).
template <bool kSeveralQueues>
class ResourceBarrierPlanner {
 public:
  ResourceBarrierPlanner(ResourceId id, const PlannedResource& resource, std::span<const Use> uses,
                         std::span<const PassId> order, EmittedBarriers& out)
      : id_(id), resource_(resource), uses_(uses), order_(order), out_(out) {
    image_ = resource.desc.type == ResourceType::Image;
    if (isTransient(resource.kind)) return;
    layout_ = resource.initialState.layout;
    // The initial state stands for work before the frame on whichever queue
    // uses the resource first (cross-frame, cross-queue sync is the executor's).
    const AccessFlag writes = writeBits(resource.initialState.access);
    if (any(writes)) {
      written_ = true;
      writeExternal_ = true;
      writeStages_ = resource.initialState.stages;
      writeAccess_ = writes;
    } else {
      externalWait_ = resource.initialState.stages;
    }
  }

  void run(PipelineStage aliasedStages, AccessFlag aliasedWrites, bool aliased) {
    std::size_t readsEnd = 0;  // where the current run of reads ends, once looked for
    for (std::size_t i = 0; i < uses_.size();) {
      if (uses_[i].write) {
        write(uses_[i], (i == 0) & aliased, aliasedStages, aliasedWrites);
        ++i;
        continue;
      }
      if (kSeveralQueues && i >= readsEnd) {
        readsEnd = i;
        QueueMask queues = QueueMask::None;
        while (readsEnd < uses_.size() && !uses_[readsEnd].write) queues |= toMask(uses_[readsEnd++].queue);
        if (queueCount(queues) > 1) {
          sharedReads(i, readsEnd);
          i = readsEnd;
          continue;
        }
      }
      read(i);
      ++i;
    }
    if (!isTransient(resource_.kind)) finish();
  }

 private:
  // Where queue q's state is: a resource used on one queue keeps only that queue's.
  static uint32_t slot(QueueClass q) { return kSeveralQueues ? queueIndex(q) : 0; }

  // (The planner's conditions combine bools with & and |, not && and ||: their
  // operands are cheap, and each short-circuit would be a branch that flips
  // with the graph's data.)
  bool sameQueueWrite(QueueClass q) const { return written_ & (writeExternal_ | (writeQueue_ == q)); }

  bool crossQueuePrior(QueueClass q) const {
    if constexpr (!kSeveralQueues) return false;
    // Written on another queue, or read or transitioned there since.
    static_assert(kQueueClassCount == 3);
    const uint32_t waitingQueues = any(queues_[0].waitStages) + any(queues_[1].waitStages) +
                                   any(queues_[2].waitStages) - any(queues_[slot(q)].waitStages);
    return (written_ & !sameQueueWrite(q)) | (waitingQueues != 0);
  }

  // The source scope every barrier on queue q needs: what already ran on q,
  // plus the last write unless an earlier barrier on q chained after it.
  Barrier sourceOn(QueueClass q) const {
    Barrier b{.resource = id_};
    b.srcStages = queues_[slot(q)].waitStages | externalWait_;
    const bool unchained = sameQueueWrite(q) & !queues_[slot(q)].writeChained;
    b.srcStages |= keptIf(unchained, writeStages_);
    b.srcAccess = keptIf(unchained, writeAccess_);
    return b;
  }

  void setLayouts(Barrier& b, Layout newLayout) const {
    // Buffers have no layout: Undefined (0) for them, by a mask.
    const auto imageMask = maskIf<uint8_t>(image_);
    b.oldLayout = static_cast<Layout>(static_cast<uint8_t>(layout_) & imageMask);
    b.newLayout = static_cast<Layout>(static_cast<uint8_t>(newLayout) & imageMask);
    b.discard = b.discard | (image_ & (layout_ == Layout::Undefined));
  }

  void emit(PassId pass, bool after, const Barrier& b, QueueClass q) {
    out_.add(pass, after, b);
    QueueSync& qs = queues_[slot(q)];
    if (!any(b.dstStages)) return;  // nothing on this queue can chain through it
    qs.waitStages |= b.dstStages;
    if (sameQueueWrite(q)) qs.writeChained = true;
  }

  void write(const Use& u, bool aliased, PipelineStage aliasedStages, AccessFlag aliasedWrites) {
    Barrier b = sourceOn(u.queue);
    b.dstStages = u.stages;
    b.dstAccess = u.access;
    const bool layoutChange = image_ & (layout_ != u.layout);
    // Taking over memory: after every access of the previous occupants (same queue).
    b.srcStages |= keptIf(aliased, aliasedStages);
    b.srcAccess |= keptIf(aliased, aliasedWrites);
    b.discard = aliased;
    b.srcStages |= keptIf(layoutChange & crossQueuePrior(u.queue), u.stages);  // chain with the semaphore wait
    setLayouts(b, u.layout);
    if (any(b.srcStages) | layoutChange | aliased) out_.add(u.pass, false, b);

    layout_ = u.layout;
    written_ = true;
    writeExternal_ = false;
    writeQueue_ = u.queue;
    writeStages_ = u.stages;
    writeAccess_ = writeBits(u.access);
    externalWait_ = PipelineStage::None;
    if constexpr (kSeveralQueues) {
      queues_ = kAfterWriteOn[queueIndex(u.queue)];
    } else {
      queues_[0] = {};
    }
  }

  // A read of a version only one queue reads.
  void read(std::size_t i) {
    const Use& u = uses_[i];
    QueueSync& qs = queues_[slot(u.queue)];
    const bool layoutChange = image_ & (layout_ != u.layout);
    const bool pendingWrite = (sameQueueWrite(u.queue) & any(writeAccess_)) | qs.transitioned;
    const bool covered = qs.allVisible | (contains(qs.visibleStages, u.stages) & contains(qs.visibleAccess, u.access));
    if ((!layoutChange) & ((!pendingWrite) | covered)) {
      qs.waitStages |= u.stages;
      return;
    }
    Barrier b = sourceOn(u.queue);
    // Later readers in the same layout share this barrier.
    b.dstStages = u.stages;
    b.dstAccess = u.access;
    for (std::size_t k = i + 1; k < uses_.size() && ((!uses_[k].write) & ((!image_) | (uses_[k].layout == u.layout))); ++k) {
      b.dstStages |= uses_[k].stages;
      b.dstAccess |= uses_[k].access;
    }
    b.srcStages |= keptIf(layoutChange & crossQueuePrior(u.queue), u.stages);  // chain with the semaphore wait
    setLayouts(b, u.layout);
    emit(u.pass, false, b, u.queue);
    if (layoutChange) {
      layout_ = u.layout;
      qs.visibleStages = b.dstStages;
      qs.visibleAccess = b.dstAccess;
      qs.allVisible = false;
      qs.transitioned = true;
    } else {
      qs.visibleStages |= b.dstStages;
      qs.visibleAccess |= b.dstAccess;
    }
    qs.waitStages |= u.stages;
  }

  // A version read on several queues: one layout for all readers, one transition.
  void sharedReads(std::size_t begin, std::size_t end) {
    Layout readLayout = uses_[begin].layout;
    for (std::size_t k = begin + 1; k < end && image_; ++k) {
      const auto merged = mergeLayouts(readLayout, uses_[k].layout);
      readLayout = merged ? *merged : Layout::General;
    }
    const bool produced = begin > 0;  // else the version is the frame-start content
    const Use& host = produced ? uses_[begin - 1] : uses_[begin];
    const QueueClass q = host.queue;
    const bool layoutChange = image_ && layout_ != readLayout;

    Barrier b = produced ? Barrier{.resource = id_, .srcStages = writeStages_, .srcAccess = writeAccess_}
                         : sourceOn(q);
    for (std::size_t k = begin; k < end; ++k) {
      if (uses_[k].queue != q) continue;
      b.dstStages |= uses_[k].stages;
      b.dstAccess |= uses_[k].access;
    }
    setLayouts(b, readLayout);
    const bool needed = layoutChange || (produced ? any(b.dstStages) : any(b.srcAccess));
    if (needed) {
      emit(host.pass, produced, b, q);
      QueueSync& qs = queues_[slot(q)];
      qs.visibleStages = b.dstStages;
      qs.visibleAccess = b.dstAccess;
      qs.transitioned = layoutChange;
    }
    // Readers on other queues of a frame-start version wait for the first
    // reader's transition; a produced version's signal already covers it.
    if (layoutChange && !produced) {
      for (std::size_t k = begin; k < end; ++k) {
        if (uses_[k].queue != q) out_.handoffs.push_back({host.pass, uses_[k].pass, id_, uses_[k].stages});
      }
    }
    layout_ = readLayout;
    for (std::size_t k = begin; k < end; ++k) queues_[slot(uses_[k].queue)].waitStages |= uses_[k].stages;
  }

  void finish() {
    const ResourceState& final = resource_.finalState;
    if (uses_.empty()) {
      if (!image_ || layout_ == final.layout) return;
      Barrier b{.resource = id_,
                .srcStages = resource_.initialState.stages,
                .dstStages = final.stages,
                .srcAccess = writeBits(resource_.initialState.access),
                .dstAccess = final.access};
      setLayouts(b, final.layout);
      out_.finals.push_back({b, order_.empty() ? PassId{} : order_.back(), kInvalidIndex});
      return;
    }
    const Use& host = uses_.back();
    Barrier b = sourceOn(host.queue);
    b.srcStages |= host.stages;
    b.dstStages = final.stages;
    b.dstAccess = final.access;
    const bool layoutChange = image_ && layout_ != final.layout;
    const bool pendingWrite = any(b.srcAccess);
    const bool nextWrites = any(writeBits(final.access));
    if (!layoutChange && !(any(final.stages) && (pendingWrite || nextWrites))) return;
    setLayouts(b, final.layout);
    out_.finals.push_back({b, host.pass, kInvalidIndex});
    // Last readers on other queues must finish before the host's queue changes the layout.
    if (!kSeveralQueues || host.write) return;
    for (auto it = uses_.rbegin(); it != uses_.rend() && !it->write; ++it) {
      if (it->queue != host.queue) out_.handoffs.push_back({it->pass, host.pass, id_, host.stages});
    }
  }

  ResourceId id_;
  const PlannedResource& resource_;
  std::span<const Use> uses_;
  std::span<const PassId> order_;
  EmittedBarriers& out_;

  bool image_ = false;
  Layout layout_ = Layout::Undefined;
  bool written_ = false;
  bool writeExternal_ = false;  // the "write" is the initial state: same queue as anyone
  QueueClass writeQueue_ = QueueClass::Graphics;
  PipelineStage writeStages_ = PipelineStage::None;
  AccessFlag writeAccess_ = AccessFlag::None;
  PipelineStage externalWait_ = PipelineStage::None;  // read-only initial state's stages
  std::array<QueueSync, kSeveralQueues ? kQueueClassCount : 1> queues_{};
};

}  // namespace

BarrierPlan planBarriers(const RenderGraph& graph, std::span<const PassId> order,
                         std::span<const PlannedResource> resources, std::span<const ResourceId> aliases,
                         std::span<const PipelineStage> takeOverWaits) {
  BarrierPlan plan;
  planBarriers(graph, order, resources, aliases, takeOverWaits, plan);
  return plan;
}

void planBarriers(const RenderGraph& graph, std::span<const PassId> order, std::span<const PlannedResource> resources,
                  std::span<const ResourceId> aliases, std::span<const PipelineStage> takeOverWaits, BarrierPlan& plan) {
  const auto resourceCount = static_cast<uint32_t>(resources.size());
  BarrierPlan::Scratch& scratch = plan.scratch;
  const UseTable uses = collectUses(graph, order, resourceCount, scratch);

  using Footprint = BarrierPlan::Scratch::Footprint;
  const std::vector<Footprint>& footprints = scratch.footprints;

  plan.finals.clear();
  plan.handoffs.clear();
  // At most one barrier per use (a write's, a read's, or a run of shared
  // reads' one transition): written in place, no capacity check per barrier.
  if (scratch.entries.size() < uses.uses.size()) scratch.entries.resize(uses.uses.size());
  EmittedBarriers emitted{scratch.entries.data(), plan.finals, plan.handoffs};
  const std::vector<TakeOver>& takeOvers = findTakeOvers(resources, aliases, uses.lastUse, footprints, scratch);
  for (uint32_t r = 0; r < resourceCount; ++r) {
    const TakeOver& takeOver = takeOvers[r];
    PipelineStage aliasedStages = takeOver.stages;
    // Occupants on other queues: chain with the semaphore waits that ordered them first.
    if (r < takeOverWaits.size()) aliasedStages |= keptIf(takeOver.aliased, takeOverWaits[r]);
    // (desc.queues: the queues of the resource's uses.)
    if (queueCount(resources[r].desc.queues) > 1) {
      ResourceBarrierPlanner<true>(ResourceId{r}, resources[r], uses.of(r), order, emitted)
          .run(aliasedStages, takeOver.writes, takeOver.aliased);
    } else {
      ResourceBarrierPlanner<false>(ResourceId{r}, resources[r], uses.of(r), order, emitted)
          .run(aliasedStages, takeOver.writes, takeOver.aliased);
    }
  }

  // Group by pass (counting sort keeps resource order within a pass): each
  // pass's two ranges from the counts, which turn into cursors in place.
  std::vector<uint32_t>& cursor = scratch.slotFirst;
  cursor.assign(graph.passCount() * 2, 0);
  const std::span<const EmittedBarriers::Entry> entries{scratch.entries.data(), emitted.next};
  for (const EmittedBarriers::Entry& e : entries) ++cursor[e.slot];
  plan.before.resize(graph.passCount());
  plan.after.resize(graph.passCount());
  uint32_t start = 0;
  for (uint32_t p = 0; p < graph.passCount(); ++p) {
    plan.before[p] = {start, cursor[2 * p]};
    cursor[2 * p] = start;
    start += plan.before[p].count;
    plan.after[p] = {start, cursor[2 * p + 1]};
    cursor[2 * p + 1] = start;
    start += plan.after[p].count;
  }
  plan.barriers.resize(entries.size());
  for (const EmittedBarriers::Entry& e : entries) plan.barriers[cursor[e.slot]++] = e.barrier;
}

}  // namespace sg::graph
