#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/memory_requirements.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace sg::graph {

struct MemoryPlan {
  std::vector<MemoryPlacement> placements;  // per resource; unplaced unless a used transient
  std::vector<Range> aliasesWith;           // per resource, into `aliases` (see PlannedResource::aliasesWith)
  std::vector<ResourceId> aliases;
  std::vector<Heap> heaps;
  uint64_t heapBytes = 0;
  uint64_t heapBytesWithoutAliasing = 0;

  std::span<const ResourceId> aliasesOf(ResourceId r) const { return slice(aliases, aliasesWith[r.index]); }
};

// Places every used transient in a heap, from real memory requirements
// (indexed by ResourceId; other resources' entries are ignored).
//
// Heaps are keyed by memoryTypeBits compatibility and by queue: two transients
// only share memory if all their accesses are on the same logical queue
// (handing memory over between queues would need a semaphore); transients used
// by several queues, and all transients when aliasing is off, go to heaps where
// nothing aliases. Persistent, history and imported resources are never placed.
//
// Aliasing is a sweep over the order, like linear-scan register allocation:
// at each position the transients whose lifetime ([firstUse, lastUse]) ended
// give their range back to the heap's free list (coalesced), then the ones
// starting there (largest first) take the best-fitting aligned free range, or
// grow the heap. O(n log n) whatever the lifetimes; sorting all transients by
// size and first-fitting each against every overlapping one packs a little
// tighter in contrived cases but costs O(n k log k) for k overlapping lifetimes.
MemoryPlan placeTransients(std::span<const PlannedResource> resources,
                           std::span<const MemoryRequirements> requirements, bool enableAliasing);
// The same into `plan`, reusing its memory.
void placeTransients(std::span<const PlannedResource> resources, std::span<const MemoryRequirements> requirements,
                     bool enableAliasing, MemoryPlan& plan);

}  // namespace sg::graph
