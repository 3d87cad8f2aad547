#pragma once
// The free bytes of one aliasing heap during placement, and who used them
// last: what a transient taking them over aliases with, and waits for.

#include <shadelgraph/graph/queue.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace sg::graph {

// `value` rounded up to a multiple of `alignment` (1 or 0: unchanged). Inline:
// the best-fit search calls it for every candidate.
inline uint64_t alignUp(uint64_t value, uint64_t alignment) {
  if (alignment <= 1) return value;
  if ((alignment & (alignment - 1)) == 0) return (value + alignment - 1) & ~(alignment - 1);  // Vulkan's case
  return (value + alignment - 1) / alignment * alignment;
}

// The heap as blocks in address order, used and free, covering [0, heapSize)
// (boundary tags: a release turns its used block free in place and finds its
// neighbours by link, a take-over splits in place). A free block is a fragment
// of one last user (never merged across users: each must be reported when
// taken over) and holds the queues allowed to take it over yet: its last
// user's at once, the others once a semaphore wait proves that work done. A
// queue sees adjacent free blocks it may take as one range, a *run*; each
// queue's runs sit in size-class bins (powers of two in quarters, a bitmap
// of the non-empty ones), so best fit looks at one or two bins instead of
// every fragment. Placement decisions are those of a walk over all fragments
// by offset (LinearFreeRanges, the oracle in the tests and the cheaper choice
// for small heaps).
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
  // Appends the last users of the bytes taken to `previous`; `block` names the
  // range for release(). A size of 0 takes one byte.
  uint64_t allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                    std::vector<uint32_t>& previous, uint32_t& block);
  // allocate()'s `block`, last used by `occupant` (one release per occupant),
  // is free for `queues`.
  void release(uint32_t block, uint32_t occupant, QueueMask queues);
  // What is still free of `occupant`'s block may now be taken by `queues` too.
  void allow(uint32_t occupant, QueueMask queues);

  // The ranges `queue` may take, adjacent fragments merged, by offset (for tests and dumps).
  std::vector<Span> rangesFor(QueueClass queue) const;
  std::size_t fragmentCount() const;
  // The blocks tile [0, heapSize) in address order and every queue's bins
  // hold exactly its runs (for tests).
  bool consistent(uint64_t heapSize) const;

 private:
  static constexpr uint32_t kNone = ~0u;
  static constexpr uint32_t kNobody = ~0u;  // alignment padding: never used
  static constexpr uint32_t kBins = 256;

  // Where a block heading a run of one queue sits in that queue's bins.
  struct RunLink {
    uint64_t end = 0;  // of the run
    uint32_t binPrev = kNone;
    uint32_t binNext = kNone;
  };
  struct Block {
    uint64_t begin = 0;
    uint64_t end = 0;
    uint32_t prev = kNone;  // address order
    uint32_t next = kNone;
    uint32_t occupant = kNobody;  // free: the last user
    uint32_t piecePrev = kNone;   // free: the last user's other fragments
    uint32_t pieceNext = kNone;
    QueueMask queues = QueueMask::None;  // free: who may take it over
    bool used = false;
    std::array<uint8_t, kQueueClassCount> runClass{};  // the size class of the run it heads, per queue
    std::array<RunLink, kQueueClassCount> runs{};  // valid where it heads a run of that queue
  };
  struct Bins {
    std::array<uint64_t, kBins / 64> nonEmpty{};
    std::array<uint32_t, kBins> first{};  // valid where nonEmpty
  };

  // (A used block has no queues: newBlock() clears them and only free blocks
  // are given any, so the queues alone tell.)
  bool freeFor(uint32_t b, QueueMask q) const { return b != kNone && any(blocks_[b].queues & q); }
  uint32_t runHead(uint32_t b, uint32_t queue) const;
  void bin(uint32_t head, uint32_t queue, uint64_t end);
  void unbin(uint32_t head, uint32_t queue);
  void resize(uint32_t head, uint32_t queue, uint64_t end);  // a binned run, same head
  uint32_t bestFit(uint32_t queue, uint64_t size, uint64_t alignment) const;
  // Free blocks from `first` (kNone: none) that overlap [offset, end) become
  // one used block there (appended at the top when none do); returns it.
  uint32_t take(uint32_t first, uint64_t offset, uint64_t end, std::vector<uint32_t>& previous);
  // Free block `b` may now be taken by `queues` (none of which it had): joins their runs.
  void joinRuns(uint32_t b, QueueMask queues);
  uint32_t newBlock();
  void insertAfter(uint32_t b, uint32_t after);  // kNone: at the bottom
  void unlink(uint32_t b);
  void addPiece(uint32_t b);
  void removePiece(uint32_t b);

  std::vector<Block> blocks_;
  std::vector<uint32_t> unusedBlocks_;  // recycled indices into blocks_
  std::vector<uint32_t> pieces_;        // per occupant: its first free fragment
  std::array<Bins, kQueueClassCount> bins_{};
  uint32_t bottom_ = kNone;
  uint32_t top_ = kNone;
  QueueMask queues_ = ~QueueMask::None;
};

}  // namespace sg::graph
