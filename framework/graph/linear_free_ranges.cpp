#include <shadelgraph/graph/linear_free_ranges.hpp>

#include <algorithm>

namespace sg::graph {

uint64_t LinearFreeRanges::allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                                    std::vector<uint32_t>& previous, uint32_t& block) {
  if (size == 0) size = 1;  // as FreeRanges
  const uint64_t offset = allocate(size, alignment, queue, heapSize, previous);
  block = static_cast<uint32_t>(blocks_.size());
  blocks_.push_back({offset, offset + size});
  return offset;
}

void LinearFreeRanges::release(uint32_t block, uint32_t occupant, QueueMask queues) {
  const Span span = blocks_[block];
  if (occupant >= occupants_.size()) occupants_.resize(occupant + 1);
  occupants_[occupant] = span;
  release(span.begin, span.end - span.begin, occupant, queues);
}

void LinearFreeRanges::allow(uint32_t occupant, QueueMask queues) {
  const Span span = occupants_[occupant];
  allow(span.begin, span.end - span.begin, occupant, queues);
}

void LinearFreeRanges::clear(QueueMask queues) {
  fragments_.clear();
  blocks_.clear();
  queues_ = queues;
}

uint64_t LinearFreeRanges::allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
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

void LinearFreeRanges::release(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues) {
  const auto at = std::lower_bound(fragments_.begin(), fragments_.end(), offset,
                                   [](const Fragment& f, uint64_t o) { return f.begin < o; });
  fragments_.insert(at, {offset, offset + size, occupant, queues & queues_});
}

void LinearFreeRanges::allow(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues) {
  queues &= queues_;
  if (!any(queues)) return;
  auto it = std::lower_bound(fragments_.begin(), fragments_.end(), offset,
                             [](const Fragment& f, uint64_t o) { return f.end <= o; });
  for (; it != fragments_.end() && it->begin < offset + size; ++it) {
    if (it->occupant == occupant) it->queues |= queues;
  }
}

std::vector<LinearFreeRanges::Span> LinearFreeRanges::rangesFor(QueueClass queue) const {
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

void LinearFreeRanges::splice(std::size_t first, std::size_t last, const Fragment* rest, std::size_t count) {
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

}  // namespace sg::graph
