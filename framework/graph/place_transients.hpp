#pragma once

#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/memory_requirements.hpp>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace sg::graph {

namespace detail {

// Free byte ranges of one aliasing heap, and who used each freed range last
// (that transient is what the next one placed there aliases with).
class FreeList {
 public:
  // Best fit: the smallest free range holding `size` bytes at `alignment`;
  // otherwise at the end of the heap (which grows). Appends the transients
  // that last used the range to `previous`.
  uint64_t allocate(uint64_t size, uint64_t alignment, uint64_t& heapSize, std::vector<uint32_t>& previous);
  void release(uint64_t offset, uint64_t size, uint32_t occupant);
  void clear() {
    blocks_.clear();
    lastUsers_.clear();
  }

 private:
  struct Block {
    uint64_t begin;
    uint64_t end;
  };
  struct LastUser {
    uint64_t begin;
    uint64_t end;
    uint32_t occupant;
  };

  void takeOver(uint64_t begin, uint64_t end, std::vector<uint32_t>& previous);

  std::vector<Block> blocks_;        // by offset, never adjacent
  std::vector<LastUser> lastUsers_;  // freed ranges by offset, not coalesced
};

}  // namespace detail

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
  uint64_t heapBytes = 0;
  uint64_t heapBytesWithoutAliasing = 0;

  std::span<const ResourceId> aliasesOf(ResourceId r) const { return slice(aliases, aliasesWith[r.index]); }

  // placeTransients()'s working memory, kept so that the next call reuses it.
  struct Scratch {
    std::vector<TransientLifetime> transients;
    std::vector<uint32_t> byStart;  // into transients
    std::vector<uint32_t> byEnd;
    std::vector<uint32_t> bucketStarts;
    std::vector<detail::FreeList> freeLists;  // per heap (aliasing heaps only use theirs)
    std::vector<uint64_t> unaliasedSize;      // per heap: its size if nothing aliased
    std::vector<std::pair<uint32_t, uint32_t>> aliasPairs;
    std::vector<uint32_t> previous;
  } scratch;
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
// The same from the used transients alone (in any order; each id once), for
// `resourceCount` resources: what PlanCompiler gathers in the sweep that also
// collects requirements, so that placement does not walk the resources again.
void placeTransients(std::span<const TransientLifetime> transients, uint32_t resourceCount,
                     std::span<const MemoryRequirements> requirements, bool enableAliasing, MemoryPlan& plan);

}  // namespace sg::graph
