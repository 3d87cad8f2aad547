#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/render_graph.hpp>

#include <span>
#include <vector>

namespace sg::graph {

// What one kept pass does to one resource (its accesses merged).
struct ResourceUse {
  PassId pass;
  QueueClass queue = QueueClass::Graphics;
  PipelineStage stages = PipelineStage::None;
  AccessFlag access = AccessFlag::None;
  Layout layout = Layout::Undefined;
  bool write = false;
};  // 12 bytes

struct BarrierPlan {
  std::vector<Barrier> barriers;  // grouped by pass: each pass's before, then its after
  std::vector<Range> before;      // per pass, into `barriers`
  std::vector<Range> after;       // per pass, into `barriers`
  std::vector<FinalBarrier> finals;  // `batch` left unset: queues are assigned later
  // Extra cross-queue orderings that layout hand-offs rely on; assignQueues()
  // turns them into semaphore waits like ordinary dependencies.
  std::vector<Dependency> handoffs;

  // planBarriers()'s working memory, kept so that the next call reuses it.
  struct Scratch {
    // Uses grouped by resource, each group in execution order.
    std::vector<uint32_t> firstUse;  // per resource, plus one
    std::vector<uint32_t> lastUse;   // per resource: position in the order of its last use
    std::vector<ResourceUse> uses;
    std::vector<uint32_t> cursor;
    // Uses in execution order, each with its resource, before grouping.
    struct UseInOrder {
      uint32_t resource;
      ResourceUse use;
    };
    std::vector<UseInOrder> inOrder;
    // Per resource: every stage and write, what a transient taking over its memory waits for.
    struct Footprint {
      PipelineStage stages = PipelineStage::None;
      AccessFlag writes = AccessFlag::None;
    };
    std::vector<Footprint> footprints;
    // Per resource: every stage and write of the earlier occupants of its memory, if any.
    struct TakeOver {
      PipelineStage stages = PipelineStage::None;
      AccessFlag writes = AccessFlag::None;
      bool aliased = false;
    };
    std::vector<TakeOver> takeOvers;
    std::vector<uint32_t> aliasListEnds;  // per alias, plus one: how many resources' lists end there
    // Barriers as they are found (resource by resource), before grouping by pass.
    struct Entry {
      uint32_t slot;  // pass * 2, + 1 for "after the pass"
      Barrier barrier;
    };
    std::vector<Entry> entries;
    std::vector<uint32_t> slotFirst;
  } scratch;

  std::span<const Barrier> beforePass(PassId p) const { return slice(barriers, before[p.index]); }
  std::span<const Barrier> afterPass(PassId p) const { return slice(barriers, after[p.index]); }
};

// The barriers of every kept pass, walking each resource's uses in `order`.
//
// - Same queue: the narrowest stages and accesses. read -> read with the same
//   layout: none; write -> write: one; write -> read: one, and consecutive
//   readers with the same layout share it (its destination covers all of them);
//   read -> write: execution only (srcAccess None) once the write was made available.
// - Across queues the semaphore wait carries the memory dependency; a barrier
//   only transitions the layout, with srcStages = its own stages so it chains
//   with the wait.
// - A version read on more than one queue is read in one layout (General if the
//   readers disagree, DepthReadOnly for depth test + sampling). The transition
//   happens once, on the producer's queue right after the producer
//   (barriersAfter), so no two queues ever transition the same image. For a
//   version present at frame start, the first reader transitions it and the
//   other queues' readers wait for it (a hand-off).
// - A transient that takes over aliased memory gets a discard barrier whose
//   source covers every stage and write of the previous occupants and, where
//   they ran on another queue, the stages of the semaphore waits that ordered
//   them before it (`takeOverWaits`, per resource; may be empty), to chain with them.
// - External resources start in their initial state; final barriers leave them
//   in their final state, after their last use (hand-offs make the other
//   queues' last readers finish first).
// `aliases` is the storage the resources' aliasesWith ranges point into.
BarrierPlan planBarriers(const RenderGraph& graph, std::span<const PassId> order,
                         std::span<const PlannedResource> resources, std::span<const ResourceId> aliases,
                         std::span<const PipelineStage> takeOverWaits = {});
// The same into `plan`, reusing its memory.
void planBarriers(const RenderGraph& graph, std::span<const PassId> order, std::span<const PlannedResource> resources,
                  std::span<const ResourceId> aliases, std::span<const PipelineStage> takeOverWaits, BarrierPlan& plan);

}  // namespace sg::graph
