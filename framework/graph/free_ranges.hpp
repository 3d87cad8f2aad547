#pragma once
// The free bytes of one aliasing heap during placement, and who used them
// last: what a transient taking them over aliases with, and waits for.

#include <shadelgraph/graph/queue.hpp>

#include <cstdint>
#include <vector>

namespace sg::graph {

// `value` rounded up to a multiple of `alignment` (1 or 0: unchanged). Inline:
// the best-fit walk calls it for every run.
inline uint64_t alignUp(uint64_t value, uint64_t alignment) {
  if (alignment <= 1) return value;
  if ((alignment & (alignment - 1)) == 0) return (value + alignment - 1) & ~(alignment - 1);  // Vulkan's case
  return (value + alignment - 1) / alignment * alignment;
}

// Free ranges as fragments by offset, one per last user (never merged across
// users: each must be reported when taken over). A fragment also holds the
// queues allowed to take it over yet: its last user's at once, the others once
// a semaphore wait proves that work done. A queue sees adjacent fragments it may
// take as one range. One flat array: every operation is a binary search or a
// walk over the fragments, and the array is reused from heap to heap.
class FreeRanges {
 public:
  struct Span {
    uint64_t begin = 0;
    uint64_t end = 0;
    friend bool operator==(Span, Span) = default;
  };

  // Empties the heap; only `queues` will ever take ranges from it.
  void clear(QueueMask queues);
  // Best fit: the smallest range `queue` may take (merged across fragments)
  // holding `size` bytes at `alignment`, the lowest offset on a tie; otherwise
  // at the top of the heap, starting inside the range `queue` may take that
  // ends there (`heapSize` grows; alignment padding becomes free for every
  // queue). `queue` must be one queue; with none or several, always the top.
  // Appends the last users of the bytes taken to `previous`.
  uint64_t allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                    std::vector<uint32_t>& previous);
  // [offset, offset + size), last used by `occupant`, is free for `queues`.
  void release(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues);
  // What is still free of `occupant`'s range [offset, offset + size) may now be taken by `queues` too.
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
  QueueMask queues_ = ~QueueMask::None;
};

}  // namespace sg::graph
