#pragma once
// The linear FreeRanges that placement used until session 12 (a sorted array
// of fragments, a walk over all of them per allocation), kept as the oracle
// the block list must agree with, decision for decision.

#include <shadelgraph/graph/free_ranges.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sg::graph::testing {

class LinearFreeRanges {
 public:
  using Span = FreeRanges::Span;

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

inline void LinearFreeRanges::clear(QueueMask queues) {
  fragments_.clear();
  queues_ = queues;
}

inline uint64_t LinearFreeRanges::allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                              std::vector<uint32_t>& previous) {
  const QueueMask taker = queueCount(queue) == 1 ? queue : QueueMask::None;
  // One walk over runs of adjacent fragments `taker` may take, the best fitting kept.
  std::size_t best = 0, bestEnd = 0;  // fragments of the best run: [best, bestEnd)
  uint64_t bestBegin = 0, bestLength = ~uint64_t{0};
  bool found = false;
  uint64_t runBegin = 0, runEnd = 0;  // the last run seen
  std::size_t runFirst = 0, runLast = 0;
  const Fragment* const fragments = fragments_.data();
  const std::size_t n = fragments_.size();
  for (std::size_t i = 0; i < n;) {
    if (!any(fragments[i].queues & taker)) {
      ++i;
      continue;
    }
    runFirst = i;
    runBegin = fragments[i].begin;
    runEnd = fragments[i].end;
    for (++i; i < n && fragments[i].begin == runEnd && any(fragments[i].queues & taker); ++i) runEnd = fragments[i].end;
    runLast = i;
    const uint64_t length = runEnd - runBegin;
    if (length < size || length >= bestLength || alignUp(runBegin, alignment) + size > runEnd) continue;
    best = runFirst;
    bestEnd = runLast;
    bestBegin = runBegin;
    bestLength = length;
    found = true;
  }
  const bool inRun = runLast == n && n != 0;  // the last fragment ends a run `taker` may take

  uint64_t offset = 0;
  if (found) {
    offset = alignUp(bestBegin, alignment);
  } else {
    // Grow the heap, starting inside the last run if it ends at the top.
    const bool fromTop = inRun && runEnd == heapSize;
    best = fromTop ? runFirst : n;
    offset = alignUp(fromTop ? runBegin : heapSize, alignment);
    if (offset > heapSize) {  // fresh padding below the new range: free for every queue
      fragments_.push_back({heapSize, offset, kNobody, queues_});
    }
    heapSize = offset + size;
    bestEnd = fragments_.size();
  }

  // Take [offset, end) out of the fragments that overlap it; report their users.
  const uint64_t end = offset + size;
  std::size_t first = best;
  while (first < bestEnd && fragments_[first].end <= offset) ++first;
  std::size_t last = first;
  for (; last < bestEnd && fragments_[last].begin < end; ++last) {
    if (fragments_[last].occupant != kNobody) previous.push_back(fragments_[last].occupant);
  }
  if (first == last) return offset;
  Fragment rest[2];
  std::size_t count = 0;
  if (fragments_[first].begin < offset) {
    rest[count] = fragments_[first];
    rest[count++].end = offset;
  }
  if (fragments_[last - 1].end > end) {
    rest[count] = fragments_[last - 1];
    rest[count++].begin = end;
  }
  splice(first, last, rest, count);
  return offset;
}

inline void LinearFreeRanges::release(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues) {
  const auto at = std::lower_bound(fragments_.begin(), fragments_.end(), offset,
                                   [](const Fragment& f, uint64_t o) { return f.begin < o; });
  fragments_.insert(at, {offset, offset + size, occupant, queues & queues_});
}

inline void LinearFreeRanges::allow(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues) {
  queues &= queues_;
  if (!any(queues)) return;
  auto it = std::lower_bound(fragments_.begin(), fragments_.end(), offset,
                             [](const Fragment& f, uint64_t o) { return f.end <= o; });
  for (; it != fragments_.end() && it->begin < offset + size; ++it) {
    if (it->occupant == occupant) it->queues |= queues;
  }
}

inline std::vector<LinearFreeRanges::Span> LinearFreeRanges::rangesFor(QueueClass queue) const {
  std::vector<Span> spans;
  for (const Fragment& f : fragments_) {
    if (!any(f.queues & toMask(queue))) continue;
    if (!spans.empty() && spans.back().end == f.begin) {
      spans.back().end = f.end;
    } else {
      spans.push_back({f.begin, f.end});
    }
  }
  return spans;
}

inline void LinearFreeRanges::splice(std::size_t first, std::size_t last, const Fragment* rest, std::size_t count) {
  const std::size_t removed = last - first;
  const auto at = fragments_.begin() + static_cast<std::ptrdiff_t>(first);
  if (count <= removed) {
    std::copy(rest, rest + count, at);
    fragments_.erase(at + static_cast<std::ptrdiff_t>(count), at + static_cast<std::ptrdiff_t>(removed));
  } else {
    std::copy(rest, rest + removed, at);
    fragments_.insert(at + static_cast<std::ptrdiff_t>(removed), rest + removed, rest + count);
  }
}

}  // namespace sg::graph::testing
