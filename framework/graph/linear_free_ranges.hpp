#pragma once
// FreeRanges' decisions from a sorted array of fragments and a walk over all
// of them per allocation: cheaper than the block list and its bins while a
// heap has few fragments (placeTransients picks by the number of transients),
// and the oracle the block list is tested against. Same interface.

#include <shadelgraph/graph/free_ranges.hpp>

#include <cstdint>
#include <vector>

namespace sg::graph {

class LinearFreeRanges {
 public:
  using Span = FreeRanges::Span;

  // As FreeRanges (free_ranges.hpp says what each does).
  void clear(QueueMask queues);
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

 private:
  static constexpr uint32_t kNobody = ~0u;  // alignment padding: never used
  struct Fragment {
    uint64_t begin;
    uint64_t end;
    uint32_t occupant;
    QueueMask queues;  // may take it over
  };

  // Replaces fragments [first, last) with `rest` (0 to 2 fragments).
  void splice(std::size_t first, std::size_t last, const Fragment* rest, std::size_t count);

  std::vector<Fragment> fragments_;
  std::vector<Span> blocks_;     // allocate()'s blocks: their ranges
  std::vector<Span> occupants_;  // per occupant released: its range
  QueueMask queues_ = ~QueueMask::None;
};

}  // namespace sg::graph
