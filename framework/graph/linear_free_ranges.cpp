#include <shadelgraph/graph/linear_free_ranges.hpp>

#include <shadelgraph/graph/branchless.hpp>

#include <algorithm>

namespace sg::graph {
namespace {

constexpr std::size_t kNone = ~std::size_t{0};

// How many of `values[0, n)` come before the one sought (`before` holds for a
// prefix of them): a binary search whose steps are conditional moves, not
// branches (std::lower_bound branches at every step, at random).
template <class T, class Before>
std::size_t countBefore(const T* values, std::size_t n, Before before) {
  if (n == 0) return 0;
  const T* base = values;
  while (n > 1) {
    const std::size_t half = n / 2;
    base = before(base[half]) ? base + half : base;
    n -= half;
  }
  return static_cast<std::size_t>(base - values) + (before(*base) ? 1 : 0);
}

}  // namespace

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
  stretches_.assign(1, kSentinel);
  blocks_.clear();
  queues_ = queues;
  hasEmpty_ = false;
}

void LinearFreeRanges::reserve(std::size_t fragments) {
  fragments_.reserve(fragments);
  stretches_.reserve(fragments + 1);
}

uint64_t LinearFreeRanges::allocate(uint64_t size, uint64_t alignment, QueueMask queue, uint64_t& heapSize,
                                    std::vector<uint32_t>& previous) {
  const QueueMask taker = queueCount(queue) == 1 ? queue : QueueMask::None;
  // Best fit: the smallest run (the first of them) that holds `size` bytes once aligned.
  // Where it is: its stretch's index (high half) and first fragment (low half)
  // in one word, one select instead of two; kSubRun set if it is a run inside
  // a mixed stretch (bestBegin), else the whole stretch.
  constexpr uint64_t kSubRun = uint64_t{1} << 63;
  uint64_t bestLength = ~uint64_t{0}, bestAt = ~uint64_t{0}, bestBegin = 0;
  const std::size_t stretchCount = stretches_.size() - 1;  // the sentinel aside
  const auto walk = [&](auto aligned) {
    const auto fits = [&](uint64_t begin, uint64_t end) {
      return (end - begin >= size) & (aligned(begin) + size <= end);
    };
    std::size_t first = 0;
    for (std::size_t k = 0; k < stretchCount; ++k) {
      const Stretch& s = stretches_[k];
      // A stretch every fragment of which `taker` may take is one run.
      const uint64_t key = (s.end - s.begin) | maskIf<uint64_t>(!(any(s.all & taker) & fits(s.begin, s.end)));  // ~0: no
      const uint64_t better = maskIf<uint64_t>(key < bestLength);
      bestLength = pick(better, key, bestLength);
      bestAt = pick(better, uint64_t{k} << 32 | first, bestAt);
      if (any(taker) && !any(s.all & taker)) [[unlikely]] {
        // Maybe some fragments: the runs of adjacent ones `taker` may take
        // (and the stretch's queues brought up to date).
        const std::size_t end = first + s.count;
        QueueMask all = ~QueueMask::None;
        for (std::size_t i = first; i < end;) {
          all &= fragments_[i].queues;
          if (!any(fragments_[i].queues & taker)) {
            ++i;
            continue;
          }
          const uint64_t runBegin = fragments_[i].begin;
          for (++i; i < end && any(fragments_[i].queues & taker); ++i) all &= fragments_[i].queues;
          const uint64_t runEnd = fragments_[i - 1].end;
          if (fits(runBegin, runEnd) && runEnd - runBegin < bestLength) {
            bestLength = runEnd - runBegin;
            bestAt = kSubRun | uint64_t{k} << 32 | first;
            bestBegin = runBegin;
          }
        }
        stretches_[k].all = all;
      }
      first += s.count;
    }
  };
  if ((alignment & (alignment - 1)) == 0) {  // a power of two (Vulkan's case), 0 or 1
    const uint64_t mask = alignment <= 1 ? 0 : alignment - 1;
    walk([mask](uint64_t v) { return (v + mask) & ~mask; });
  } else {
    walk([alignment](uint64_t v) { return alignUp(v, alignment); });
  }
  const bool found = bestAt != ~uint64_t{0};
  const std::size_t bestStretch = found ? (bestAt & ~kSubRun) >> 32 : kNone;
  const std::size_t bestFirst = bestAt & 0xffffffffu;
  if (found && !(bestAt & kSubRun)) bestBegin = stretches_[bestStretch].begin;

  std::size_t stretch = bestStretch;  // the stretch [offset, offset + size) is taken from (kNone: none)
  std::size_t stretchFirst = bestFirst;
  uint64_t offset = 0;
  if (bestStretch != kNone) {
    offset = alignUp(bestBegin, alignment);
  } else {
    // Grow the heap, starting inside the run of the last fragment if it ends at the top.
    uint64_t start = heapSize;
    if (stretchCount != 0 && stretches_[stretchCount - 1].end == heapSize) {
      const Stretch& top = stretches_[stretchCount - 1];
      const std::size_t topFirst = fragments_.size() - top.count;
      std::size_t i = fragments_.size();
      if (any(top.all & taker)) {
        i = topFirst;
      } else {
        while (i > topFirst && any(fragments_[i - 1].queues & taker)) --i;
      }
      if (i < fragments_.size()) {
        start = fragments_[i].begin;
        stretch = stretchCount - 1;
        stretchFirst = topFirst;
      }
    }
    offset = alignUp(start, alignment);
    if (offset > heapSize) {  // fresh padding below the new range: free for every queue
      fragments_.push_back({heapSize, offset, kNobody, queues_});
      if (stretchCount != 0 && stretches_[stretchCount - 1].end == heapSize) {
        Stretch& top = stretches_[stretchCount - 1];
        top.end = offset;
        ++top.count;
        top.all &= queues_;
      } else {
        stretches_.insert(stretches_.end() - 1, {heapSize, offset, 1, queues_});
      }
    }
    heapSize = offset + size;
  }
  if (stretch == kNone) {
    if (hasEmpty_) stretches_ = stretchesOfFragments();
    return offset;
  }

  // Take [offset, end) out of the fragments that overlap it; report their users.
  const uint64_t end = offset + size;
  Stretch& s = stretches_[stretch];
  const std::size_t stretchEnd = stretchFirst + s.count;
  std::size_t first = stretchFirst;
  while (first < stretchEnd && fragments_[first].end <= offset) ++first;
  std::size_t last = first;
  for (; last < stretchEnd && fragments_[last].begin < end; ++last) {
    if (fragments_[last].occupant != kNobody) previous.push_back(fragments_[last].occupant);
  }
  if (first == last) {
    if (hasEmpty_) stretches_ = stretchesOfFragments();
    return offset;
  }
  // What is left of the first and last of them (written whether or not any is, to save the branches).
  const bool restBefore = fragments_[first].begin < offset;
  const bool restAfter = fragments_[last - 1].end > end;
  Fragment rest[2] = {fragments_[first], {}};
  rest[0].end = offset;
  rest[restBefore ? 1 : 0] = fragments_[last - 1];
  rest[restBefore ? 1 : 0].begin = end;
  const std::size_t restCount = std::size_t{restBefore} + std::size_t{restAfter};
  splice(first, last, rest, restCount);
  const auto remaining = static_cast<uint32_t>(s.count + restCount - (last - first));

  // The stretch keeps what is left of it on either side of [offset, end) (and its queues, now perhaps fewer
  // than its fragments').
  const bool keepsBefore = s.begin < offset;
  const bool keepsAfter = end < s.end;
  if (!keepsBefore && !keepsAfter) {
    stretches_.erase(stretches_.begin() + static_cast<std::ptrdiff_t>(stretch));
  } else if (keepsBefore && keepsAfter && offset < end) {  // split in two
    Stretch after = s;
    after.begin = end;
    s.end = offset;
    s.count = static_cast<uint32_t>(first - stretchFirst + restBefore);
    after.count = remaining - s.count;
    stretches_.insert(stretches_.begin() + static_cast<std::ptrdiff_t>(stretch) + 1, after);
  } else {
    if (!keepsAfter) s.end = offset;
    if (!keepsBefore) s.begin = end;
    s.count = remaining;
  }
  if (hasEmpty_) stretches_ = stretchesOfFragments();
  return offset;
}

void LinearFreeRanges::release(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues) {
  queues &= queues_;
  const uint64_t end = offset + size;
  // The first stretch at or after the range, and the new fragment's index: counted, not
  // searched (a handful of stretches, and no branch).
  const std::size_t stretchCount = stretches_.size() - 1;
  std::size_t next = 0, at = 0;
  for (std::size_t k = 0; k < stretchCount; ++k) {
    const bool before = stretches_[k].begin < offset;
    next += before;
    at += stretches_[k].count & maskIf<uint64_t>(before);
  }
  fragments_.insert(fragments_.begin() + static_cast<std::ptrdiff_t>(at), {offset, end, occupant, queues});
  const bool joinsBefore = next > 0 && stretches_[next - 1].end == offset;
  const bool joinsAfter = stretches_[next].begin == end;
  if (joinsBefore) {
    Stretch& before = stretches_[next - 1];
    before.end = end;
    ++before.count;
    before.all &= queues;
    if (joinsAfter) {  // the range joins two stretches
      const Stretch& after = stretches_[next];
      before.end = after.end;
      before.count += after.count;
      before.all &= after.all;
      stretches_.erase(stretches_.begin() + static_cast<std::ptrdiff_t>(next));
    }
  } else if (joinsAfter) {
    Stretch& after = stretches_[next];
    after.begin = offset;
    ++after.count;
    after.all &= queues;
  } else {
    stretches_.insert(stretches_.begin() + static_cast<std::ptrdiff_t>(next), {offset, end, 1, queues});
  }
  if (size == 0) hasEmpty_ = true;
  if (hasEmpty_) stretches_ = stretchesOfFragments();
}

void LinearFreeRanges::allow(uint64_t offset, uint64_t size, uint32_t occupant, QueueMask queues) {
  // (The stretches' queues are left as they are: never more than their fragments'.)
  queues &= queues_;
  if (!any(queues)) return;
  const std::size_t n = fragments_.size();
  std::size_t i = countBefore(fragments_.data(), n, [offset](const Fragment& f) { return f.end <= offset; });
  for (; i < n && fragments_[i].begin < offset + size; ++i) {
    fragments_[i].queues |= fragments_[i].occupant == occupant ? queues : QueueMask::None;
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

bool LinearFreeRanges::consistent() const {
  const std::vector<Stretch> expected = stretchesOfFragments();
  if (expected.size() != stretches_.size()) return false;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const Stretch& a = expected[k];
    const Stretch& b = stretches_[k];
    if (a.begin != b.begin || a.end != b.end || a.count != b.count || !contains(a.all, b.all)) return false;
  }
  return true;
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

std::vector<LinearFreeRanges::Stretch> LinearFreeRanges::stretchesOfFragments() const {
  std::vector<Stretch> stretches;
  for (const Fragment& f : fragments_) {
    if (!stretches.empty() && stretches.back().end == f.begin) {
      stretches.back().end = f.end;
      ++stretches.back().count;
      stretches.back().all &= f.queues;
    } else {
      stretches.push_back({f.begin, f.end, 1, f.queues});
    }
  }
  stretches.push_back(kSentinel);
  return stretches;
}

}  // namespace sg::graph
