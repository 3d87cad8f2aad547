#include <shadelgraph/graph/free_ranges.hpp>

#include <bit>

// The small steps inline: they run several times per placement.
#define SG_FREE_RANGES_INLINE [[gnu::always_inline]] inline

namespace sg::graph {
namespace {

// Size class of a run's length: a power of two in quarters (monotonic in the
// length, 4 to 255 for 64-bit lengths; lengths below 8 each their own).
inline uint32_t sizeClass(uint64_t length) {
  const auto log = static_cast<uint32_t>(63 - std::countl_zero(length | 4));
  return 4 * (log - 1) + static_cast<uint32_t>(length >> (log - 2));
}

}  // namespace

void FreeRanges::clear(QueueMask queues) {
  for (const Block& b : blocks_) {
    if (!b.used && b.occupant != kNobody && b.occupant < pieces_.size()) pieces_[b.occupant] = kNone;
  }
  blocks_.clear();
  unusedBlocks_.clear();
  for (Bins& bins : bins_) bins.nonEmpty.fill(0);
  bottom_ = top_ = kNone;
  queues_ = queues;
}

SG_FREE_RANGES_INLINE uint32_t FreeRanges::runHead(uint32_t b, uint32_t queue) const {
  const QueueMask q = static_cast<QueueMask>(1u << queue);
  while (freeFor(blocks_[b].prev, q)) b = blocks_[b].prev;
  return b;
}

SG_FREE_RANGES_INLINE void FreeRanges::bin(uint32_t head, uint32_t queue, uint64_t end) {
  Bins& bins = bins_[queue];
  const uint32_t c = sizeClass(end - blocks_[head].begin);
  RunLink& link = blocks_[head].runs[queue];
  link.end = end;
  blocks_[head].runClass[queue] = static_cast<uint8_t>(c);
  link.binPrev = kNone;
  uint64_t& word = bins.nonEmpty[c / 64];
  const uint64_t bit = uint64_t{1} << (c % 64);
  link.binNext = (word & bit) ? bins.first[c] : kNone;
  if (link.binNext != kNone) blocks_[link.binNext].runs[queue].binPrev = head;
  bins.first[c] = head;
  word |= bit;
}

SG_FREE_RANGES_INLINE void FreeRanges::unbin(uint32_t head, uint32_t queue) {
  Bins& bins = bins_[queue];
  const RunLink& link = blocks_[head].runs[queue];
  if (link.binNext != kNone) blocks_[link.binNext].runs[queue].binPrev = link.binPrev;
  if (link.binPrev != kNone) {
    blocks_[link.binPrev].runs[queue].binNext = link.binNext;
    return;
  }
  const uint32_t c = blocks_[head].runClass[queue];
  bins.first[c] = link.binNext;
  if (link.binNext == kNone) bins.nonEmpty[c / 64] &= ~(uint64_t{1} << (c % 64));
}

SG_FREE_RANGES_INLINE void FreeRanges::resize(uint32_t head, uint32_t queue, uint64_t end) {
  RunLink& link = blocks_[head].runs[queue];
  if (sizeClass(end - blocks_[head].begin) == blocks_[head].runClass[queue]) {
    link.end = end;
    return;
  }
  unbin(head, queue);
  bin(head, queue, end);
}

uint32_t FreeRanges::bestFit(uint32_t queue, uint64_t size, uint64_t alignment) const {
  const Bins& bins = bins_[queue];
  // The first class holding a fitting run holds the smallest one: search it whole.
  for (uint32_t c = sizeClass(size); c < kBins; ++c) {
    uint32_t word = c / 64;
    uint64_t bits = bins.nonEmpty[word] & (~uint64_t{0} << (c % 64));
    while (bits == 0) {
      if (++word == bins.nonEmpty.size()) return kNone;
      bits = bins.nonEmpty[word];
    }
    c = word * 64 + static_cast<uint32_t>(std::countr_zero(bits));
    uint32_t best = kNone;
    uint64_t bestLength = ~uint64_t{0}, bestBegin = 0;
    for (uint32_t h = bins.first[c]; h != kNone; h = blocks_[h].runs[queue].binNext) {
      const uint64_t begin = blocks_[h].begin, end = blocks_[h].runs[queue].end;
      const uint64_t length = end - begin;
      if (length < size || length > bestLength || (length == bestLength && begin > bestBegin)) continue;
      if (alignUp(begin, alignment) + size > end) continue;
      best = h;
      bestLength = length;
      bestBegin = begin;
    }
    if (best != kNone) return best;
  }
  return kNone;
}

uint64_t FreeRanges::allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                              std::vector<uint32_t>& previous, uint32_t& block) {
  if (size == 0) size = 1;  // a used block of no bytes would split a run that nothing took
  const bool single = queueCount(queue) == 1;
  const auto q = static_cast<uint32_t>(std::countr_zero(static_cast<uint32_t>(queue)));
  uint32_t head = single ? bestFit(q, size, alignment) : kNone;
  uint64_t offset = 0;
  if (head != kNone) {
    offset = alignUp(blocks_[head].begin, alignment);
  } else {
    // Grow the heap, starting inside the run at the top if `queue` may take it.
    if (single && freeFor(top_, queue)) head = runHead(top_, q);
    offset = alignUp(head != kNone ? blocks_[head].begin : heapSize, alignment);
    if (offset > heapSize) {  // fresh padding below the new range: free for every queue
      const uint32_t padding = newBlock();
      Block& p = blocks_[padding];
      p.begin = heapSize;
      p.end = offset;
      p.occupant = kNobody;
      insertAfter(padding, top_);
      joinRuns(padding, queues_);
    }
    heapSize = offset + size;
  }
  block = take(head, offset, offset + size, previous);
  return offset;
}

uint32_t FreeRanges::take(uint32_t first, uint64_t offset, uint64_t end, std::vector<uint32_t>& previous) {
  while (first != kNone && blocks_[first].end <= offset) first = blocks_[first].next;
  const uint32_t used = newBlock();
  blocks_[used].begin = offset;
  blocks_[used].end = end;
  blocks_[used].used = true;
  if (first == kNone || blocks_[first].begin >= end) {  // above the old top
    insertAfter(used, top_);
    return used;
  }

  // The runs through the taken fragments: the first one stays where bytes are
  // left below (`kept`, shortened at the end); the others leave their bins.
  const uint32_t f = first;
  const bool lower = blocks_[f].begin < offset;
  QueueMask touched = QueueMask::None, kept = QueueMask::None;
  // Written for every queue before it is read (kept, touched): not cleared.
  std::array<uint32_t, kQueueClassCount> firstHead;
  std::array<uint64_t, kQueueClassCount> lastEnd;
  uint32_t g = f;
  QueueMask before = QueueMask::None;  // the previous taken fragment's queues
  for (uint32_t b = f; b != kNone && blocks_[b].begin < end; b = blocks_[b].next) {
    const Block& block = blocks_[b];
    g = b;
    if (block.occupant != kNobody) previous.push_back(block.occupant);
    for (auto bits = static_cast<uint32_t>(block.queues & ~before); bits != 0; bits &= bits - 1) {
      const auto q = static_cast<uint32_t>(std::countr_zero(bits));
      const auto mask = static_cast<QueueMask>(1u << q);
      const uint32_t head = b == f ? runHead(b, q) : b;
      lastEnd[q] = blocks_[head].runs[q].end;
      if (b == f && (lower || head != f)) {
        firstHead[q] = head;
        kept |= mask;
      } else {
        unbin(head, q);
      }
    }
    touched |= block.queues;
    before = block.queues;
  }

  // What is left below and above the taken bytes stays free, in place.
  const QueueMask lastQueues = blocks_[g].queues;
  uint32_t upper = kNone;
  bool newUpper = false;
  if (blocks_[g].end > end) {
    newUpper = f == g && lower;
    if (newUpper) {  // a cut out of one fragment: the part above is a new one of the same user
      upper = newBlock();
      Block& u = blocks_[upper];
      const Block& cut = blocks_[g];
      u.begin = end;
      u.end = cut.end;
      u.occupant = cut.occupant;
      u.queues = cut.queues;
      if (u.occupant != kNobody) addPiece(upper);
    } else {
      upper = g;
    }
  }
  const uint32_t below = lower ? f : blocks_[f].prev;
  const uint32_t stop = blocks_[g].next;
  for (uint32_t b = f; b != stop;) {
    const uint32_t next = blocks_[b].next;
    if (!((b == f && lower) || b == upper)) {
      unlink(b);
      if (blocks_[b].occupant != kNobody) removePiece(b);
      unusedBlocks_.push_back(b);
    }
    b = next;
  }
  if (lower) blocks_[f].end = offset;
  if (upper == g) blocks_[g].begin = end;
  insertAfter(used, below);
  if (newUpper) insertAfter(upper, used);

  // The runs left below and above (in part or whole outside the taken blocks).
  const uint32_t above = blocks_[used].next;
  for (auto bits = static_cast<uint32_t>(touched); bits != 0; bits &= bits - 1) {
    const auto q = static_cast<uint32_t>(std::countr_zero(bits));
    const auto mask = static_cast<QueueMask>(1u << q);
    if (any(kept & mask)) resize(firstHead[q], q, offset);
    if (any(lastQueues & mask) && lastEnd[q] > end) bin(above, q, lastEnd[q]);
  }
  return used;
}

void FreeRanges::joinRuns(uint32_t b, QueueMask queues) {
  const uint32_t left = blocks_[b].prev, right = blocks_[b].next;
  for (auto bits = static_cast<uint32_t>(queues); bits != 0; bits &= bits - 1) {
    const auto q = static_cast<uint32_t>(std::countr_zero(bits));
    const auto mask = static_cast<QueueMask>(1u << q);
    uint64_t end = blocks_[b].end;
    if (freeFor(right, mask)) {  // it heads its run: `b` was not in it
      end = blocks_[right].runs[q].end;
      unbin(right, q);
    }
    if (freeFor(left, mask)) {
      resize(runHead(left, q), q, end);
    } else {
      bin(b, q, end);
    }
  }
  blocks_[b].queues |= queues;
}

void FreeRanges::release(uint32_t block, uint32_t occupant, QueueMask queues) {
  Block& b = blocks_[block];
  b.used = false;
  b.occupant = occupant;
  b.queues = QueueMask::None;
  addPiece(block);
  joinRuns(block, queues & queues_);
}

void FreeRanges::allow(uint32_t occupant, QueueMask queues) {
  queues &= queues_;
  if (!any(queues) || occupant >= pieces_.size()) return;
  for (uint32_t b = pieces_[occupant]; b != kNone; b = blocks_[b].pieceNext) {
    const QueueMask added = queues & ~blocks_[b].queues;
    if (any(added)) joinRuns(b, added);
  }
}

std::vector<FreeRanges::Span> FreeRanges::rangesFor(QueueClass queue) const {
  std::vector<Span> spans;
  for (uint32_t i = bottom_; i != kNone; i = blocks_[i].next) {
    const Block& b = blocks_[i];
    if (!freeFor(i, toMask(queue))) continue;
    if (!spans.empty() && spans.back().end == b.begin) {
      spans.back().end = b.end;
    } else {
      spans.push_back({b.begin, b.end});
    }
  }
  return spans;
}

std::size_t FreeRanges::fragmentCount() const {
  std::size_t count = 0;
  for (uint32_t i = bottom_; i != kNone; i = blocks_[i].next) count += blocks_[i].used ? 0 : 1;
  return count;
}

bool FreeRanges::consistent(uint64_t heapSize) const {
  uint64_t at = 0;
  uint32_t prev = kNone;
  std::size_t runs[kQueueClassCount] = {};
  for (uint32_t i = bottom_; i != kNone; prev = i, i = blocks_[i].next) {
    const Block& b = blocks_[i];
    if (b.prev != prev || b.begin != at || b.end <= b.begin) return false;
    if (b.used && any(b.queues)) return false;  // freeFor() relies on it
    at = b.end;
    for (uint32_t q = 0; q < kQueueClassCount; ++q) {
      const auto mask = static_cast<QueueMask>(1u << q);
      if (!freeFor(i, mask) || freeFor(b.prev, mask)) continue;  // not a run's head
      uint32_t last = i;
      while (freeFor(blocks_[last].next, mask)) last = blocks_[last].next;
      if (b.runs[q].end != blocks_[last].end) return false;
      // It is in the bin of its length.
      const uint32_t c = sizeClass(b.runs[q].end - b.begin);
      if (!(bins_[q].nonEmpty[c / 64] >> (c % 64) & 1)) return false;
      uint32_t h = bins_[q].first[c];
      while (h != kNone && h != i) h = blocks_[h].runs[q].binNext;
      if (h != i) return false;
      ++runs[q];
    }
  }
  if (prev != top_ || at != heapSize) return false;
  for (uint32_t q = 0; q < kQueueClassCount; ++q) {
    std::size_t binned = 0;
    for (uint32_t c = 0; c < kBins; ++c) {
      if (!(bins_[q].nonEmpty[c / 64] >> (c % 64) & 1)) continue;
      for (uint32_t h = bins_[q].first[c]; h != kNone; h = blocks_[h].runs[q].binNext) ++binned;
    }
    if (binned != runs[q]) return false;
  }
  return true;
}

SG_FREE_RANGES_INLINE uint32_t FreeRanges::newBlock() {
  uint32_t b = 0;
  if (unusedBlocks_.empty()) {
    b = static_cast<uint32_t>(blocks_.size());
    blocks_.emplace_back();
  } else {
    b = unusedBlocks_.back();
    unusedBlocks_.pop_back();
    Block& block = blocks_[b];  // (runs are written whenever it heads one)
    block.occupant = kNobody;
    block.queues = QueueMask::None;
    block.used = false;
  }
  return b;
}

SG_FREE_RANGES_INLINE void FreeRanges::insertAfter(uint32_t b, uint32_t after) {
  Block& block = blocks_[b];
  block.prev = after;
  block.next = after == kNone ? bottom_ : blocks_[after].next;
  (after == kNone ? bottom_ : blocks_[after].next) = b;
  (block.next == kNone ? top_ : blocks_[block.next].prev) = b;
}

SG_FREE_RANGES_INLINE void FreeRanges::unlink(uint32_t b) {
  const Block& block = blocks_[b];
  (block.prev == kNone ? bottom_ : blocks_[block.prev].next) = block.next;
  (block.next == kNone ? top_ : blocks_[block.next].prev) = block.prev;
}

SG_FREE_RANGES_INLINE void FreeRanges::addPiece(uint32_t b) {
  Block& block = blocks_[b];
  if (block.occupant >= pieces_.size()) pieces_.resize(block.occupant + 1, kNone);
  block.piecePrev = kNone;
  block.pieceNext = pieces_[block.occupant];
  if (block.pieceNext != kNone) blocks_[block.pieceNext].piecePrev = b;
  pieces_[block.occupant] = b;
}

SG_FREE_RANGES_INLINE void FreeRanges::removePiece(uint32_t b) {
  const Block& block = blocks_[b];
  if (block.pieceNext != kNone) blocks_[block.pieceNext].piecePrev = block.piecePrev;
  (block.piecePrev == kNone ? pieces_[block.occupant] : blocks_[block.piecePrev].pieceNext) = block.pieceNext;
}

}  // namespace sg::graph
