#pragma once
// FreeRanges' decisions from a sorted array of fragments and a walk over all
// of them (by stretches, below) per allocation: cheaper than the block list
// and its bins while a heap has few fragments (placeTransients picks by the
// number of transients), and the oracle the block list is tested against.
// Same interface.
//
// The walk goes over *stretches*, maximal sequences of adjacent fragments
// (used memory between two stretches), each with queues every one of its
// fragments may be taken by: for such a queue the stretch is one run, judged
// without a branch; other stretches (rare) are walked fragment by fragment.
// Synthetic graphs have about three fragments per stretch. A stretch's queues
// may lag behind (allowances add queues to fragments, not to stretches, and a
// stretch split keeps them): never more than its fragments', so a lagging
// stretch only takes the slower walk, which brings its queues up to date.

#include <shadelgraph/graph/free_ranges.hpp>

#include <cstdint>
#include <vector>

namespace sg::graph {

class LinearFreeRanges {
 public:
  using Span = FreeRanges::Span;

  // As FreeRanges (free_ranges.hpp says what each does).
  void clear(QueueMask queues);
  // Room for `fragments` fragments (and as many stretches) without growing.
  void reserve(std::size_t fragments);
  uint64_t allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                    std::vector<uint32_t>& previous, uint32_t& block);
  void release(uint32_t block, uint32_t occupant, QueueMask queues);
  void allow(uint32_t occupant, QueueMask queues);
  // The same by range, without blocks (what placeTransients calls).
  uint64_t allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                    std::vector<uint32_t>& previous);
  void release(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues);
  void allow(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues);

  // The ranges `queue` may take, adjacent fragments merged, by offset (for tests and dumps).
  std::vector<Span> rangesFor(QueueClass queue) const;
  std::size_t fragmentCount() const { return fragments_.size(); }
  // Whether the stretches are those of the fragments, their queues no more than the fragments' (for tests).
  bool consistent() const;

 private:
  static constexpr uint32_t kNobody = ~0u;  // alignment padding: never used
  struct Fragment {
    uint64_t begin;
    uint64_t end;
    uint32_t occupant;
    QueueMask queues;  // may take it over
  };

  // `count` adjacent fragments (after those of the stretches before), bytes [begin, end).
  // (A count, not the first fragment's index: inserting a fragment changes one stretch only.)
  struct Stretch {
    uint64_t begin;
    uint64_t end;
    uint32_t count;
    QueueMask all;  // queues every fragment may be taken by (or fewer)
  };
  static constexpr Stretch kSentinel{~uint64_t{0}, ~uint64_t{0}, 0, QueueMask::None};

  // Replaces fragments [first, last) with `rest` (0 to 2 fragments).
  void splice(std::size_t first, std::size_t last, const Fragment* rest, std::size_t count);
  // The stretches of the fragments, from scratch.
  std::vector<Stretch> stretchesOfFragments() const;

  std::vector<Fragment> fragments_;
  // By offset, then a sentinel (begin ~0, no fragments, no queues).
  std::vector<Stretch> stretches_ = {kSentinel};
  std::vector<Span> blocks_;     // allocate()'s blocks: their ranges
  std::vector<Span> occupants_;  // per occupant released: its range
  QueueMask queues_ = ~QueueMask::None;
  // An empty fragment (a zero-byte range released) joins its neighbours in
  // ways the stretches are not kept up to date for: they are rebuilt after
  // every change then (never seen in practice).
  bool hasEmpty_ = false;
};

}  // namespace sg::graph
