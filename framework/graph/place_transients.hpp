#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/cross_queue_order.hpp>
#include <shadelgraph/graph/free_ranges.hpp>
#include <shadelgraph/graph/linear_free_ranges.hpp>
#include <shadelgraph/graph/memory_requirements.hpp>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace sg::graph {

// A used transient as placement sees it (requirements are looked up by id).
struct TransientLifetime {
  uint32_t id = kInvalidIndex;  // ResourceId index
  uint32_t firstUse = 0;        // positions in the order
  uint32_t lastUse = 0;
  QueueMask queues = QueueMask::None;
};

struct MemoryPlan {
  std::vector<MemoryPlacement> placements;  // per resource; unplaced unless a used transient
  std::vector<Range> aliasesWith;           // per resource, into `aliases` (see PlannedResource::aliasesWith)
  std::vector<ResourceId> aliases;
  std::vector<Heap> heaps;
  // Per resource: the stages of the semaphore waits that let it take over
  // memory last used on another queue; its discard barrier chains with them.
  std::vector<PipelineStage> takeOverWaits;
  uint64_t heapBytes = 0;
  uint64_t heapBytesWithoutAliasing = 0;

  std::span<const ResourceId> aliasesOf(ResourceId r) const { return slice(aliases, aliasesWith[r.index]); }

  // placeTransients()'s working memory, kept so that the next call reuses it.
  struct Scratch {
    std::vector<TransientLifetime> transients;
    std::vector<uint32_t> byStart;  // into transients
    std::vector<uint32_t> byEnd;
    std::vector<uint32_t> bucketStarts;
    std::vector<FreeRanges> freeLists;        // per heap (aliasing heaps only use theirs), many transients
    std::vector<LinearFreeRanges> linearLists;  // the same, few transients
    std::vector<uint64_t> unaliasedSize;      // per heap: its size if nothing aliased
    std::vector<std::pair<uint32_t, uint32_t>> aliasPairs;
    std::vector<uint32_t> previous;
    std::vector<uint32_t> blocks;  // per transient: its block in its heap's free ranges
    struct Allowance {
      uint32_t next;     // the next allowance at the same position (kInvalidIndex: none)
      uint32_t index;    // into transients
      QueueMask queues;  // may take over its memory
    };
    // Per position, a list through `allowances` of what becomes allowed there
    // (positions are dense: buckets instead of a heap).
    std::vector<Allowance> allowances;
    std::vector<uint32_t> firstAllowanceAt;
  } scratch;
};

// Places every used transient in a heap, from real memory requirements
// (indexed by ResourceId; other resources' entries are ignored).
//
// Heaps are keyed by memoryTypeBits compatibility; all transients go to heaps
// where nothing aliases when aliasing is off. Persistent, history and imported
// resources are never placed. A transient may take over memory another one
// used only if every use of that one is over for the queue of its first use:
// on the same queue the submission order and its discard barrier see to it;
// for uses on another queue, `queues` must show a semaphore wait of that queue,
// at or before its first use, for a batch at or after those uses (the barrier
// then chains with the wait: takeOverWaits). Without `queues` (nullptr),
// memory used on one queue goes only to transients starting on that queue, and
// memory used on several queues is never reused.
//
// Aliasing is a sweep over the order, like linear-scan register allocation:
// at each position the transients whose lifetime ([firstUse, lastUse]) ended
// give their range back to the heap's free list, for the queues they are over
// for (others are allowed later, as the waits come), then the ones starting
// there (largest first) take the best-fitting aligned free range their queue
// may take, or grow the heap. O(n log n) whatever the lifetimes; sorting all
// transients by size and first-fitting each against every overlapping one
// packs a little tighter in contrived cases but costs O(n k log k) for k
// overlapping lifetimes.
MemoryPlan placeTransients(std::span<const PlannedResource> resources,
                           std::span<const MemoryRequirements> requirements, bool enableAliasing,
                           const CrossQueueOrder* queues = nullptr);
// The same into `plan`, reusing its memory.
void placeTransients(std::span<const PlannedResource> resources, std::span<const MemoryRequirements> requirements,
                     bool enableAliasing, MemoryPlan& plan, const CrossQueueOrder* queues = nullptr);
// The same from the used transients alone (in any order; each id once), for
// `resourceCount` resources: what PlanCompiler gathers in the sweep that also
// collects requirements, so that placement does not walk the resources again.
void placeTransients(std::span<const TransientLifetime> transients, uint32_t resourceCount,
                     std::span<const MemoryRequirements> requirements, bool enableAliasing, MemoryPlan& plan,
                     const CrossQueueOrder* queues = nullptr);

}  // namespace sg::graph
