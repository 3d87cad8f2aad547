#include <shadelgraph/graph/free_ranges.hpp>
#include <shadelgraph/graph/linear_free_ranges.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace sg::graph {
namespace {

using Span = FreeRanges::Span;
constexpr QueueMask kGraphics = QueueMask::Graphics;
constexpr QueueMask kCompute = QueueMask::AsyncCompute;
constexpr QueueMask kBoth = QueueMask::Graphics | QueueMask::AsyncCompute;

// A heap whose allocations are occupants 0, 1, 2, ... in turn (release by occupant).
template <class Ranges>
struct TestHeap {
  Ranges ranges;
  uint64_t& size;
  std::vector<uint32_t> blocks;  // per occupant

  uint64_t allocate(uint64_t bytes, uint64_t alignment, QueueMask queue, std::vector<uint32_t>& previous) {
    uint32_t block = 0;
    const uint64_t offset = ranges.allocate(bytes, alignment, queue, size, previous, block);
    blocks.push_back(block);
    return offset;
  }
  void release(uint32_t occupant, QueueMask queues) { ranges.release(blocks[occupant], occupant, queues); }
  void allow(uint32_t occupant, QueueMask queues) { ranges.allow(occupant, queues); }
  std::vector<Span> rangesFor(QueueClass queue) const { return ranges.rangesFor(queue); }
  std::size_t fragmentCount() const { return ranges.fragmentCount(); }
};

// A heap of `count` ranges of `size` bytes back to back, all in use; occupant i at i * size.
template <class Ranges>
TestHeap<Ranges> filled(uint32_t count, uint64_t size, uint64_t& heapSize) {
  TestHeap<Ranges> heap{.ranges = {}, .size = heapSize, .blocks = {}};
  heap.ranges.clear(kBoth);
  std::vector<uint32_t> previous;
  for (uint32_t i = 0; i < count; ++i) EXPECT_EQ(heap.allocate(size, 1, kGraphics, previous), i * size);
  EXPECT_TRUE(previous.empty());
  return heap;
}

// Both implementations of free ranges: the block list and the linear walk.
template <class Ranges>
class FreeRangesTest : public ::testing::Test {};
using Implementations = ::testing::Types<FreeRanges, LinearFreeRanges>;
TYPED_TEST_SUITE(FreeRangesTest, Implementations);

bool consistent(const FreeRanges& ranges, uint64_t heapSize) { return ranges.consistent(heapSize); }
bool consistent(const LinearFreeRanges& ranges, uint64_t) { return ranges.consistent(); }

TYPED_TEST(FreeRangesTest, BestFitTakesTheSmallestRangeThatHolds) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(6, 100, heap);
  ranges.release(0, kGraphics);    // 100 bytes at 0
  ranges.release(2, kGraphics);  // 200 bytes at 200 (merged with 3)
  ranges.release(3, kGraphics);
  ranges.release(5, kGraphics);  // 100 bytes at 500
  std::vector<uint32_t> previous;
  // 150 bytes fit only in [200, 400); 80 bytes fit anywhere, first of the two smallest.
  EXPECT_EQ(ranges.allocate(150, 1, kGraphics, previous), 200u);
  EXPECT_EQ(previous, (std::vector<uint32_t>{2, 3}));
  previous.clear();
  EXPECT_EQ(ranges.allocate(80, 1, kGraphics, previous), 0u);
  EXPECT_EQ(previous, std::vector<uint32_t>{0});
  EXPECT_EQ(heap, 600u);
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{80, 100}, {350, 400}, {500, 600}}));
}

TYPED_TEST(FreeRangesTest, AdjacentRangesMergeForAQueueButKeepTheirLastUsers) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(3, 100, heap);
  ranges.release(1, kGraphics);
  ranges.release(0, kGraphics);
  ranges.release(2, kGraphics);
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{0, 300}}));
  EXPECT_EQ(ranges.fragmentCount(), 3u);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(250, 1, kGraphics, previous), 0u);
  EXPECT_EQ(previous, (std::vector<uint32_t>{0, 1, 2}));  // every user of the bytes taken
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{250, 300}}));
  EXPECT_EQ(heap, 300u);
}

TYPED_TEST(FreeRangesTest, AQueueTakesOnlyWhatItIsAllowedTo) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(2, 100, heap);
  ranges.release(0, kGraphics);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(100, 1, kCompute, previous), 200u);  // not allowed: grows
  EXPECT_TRUE(previous.empty());
  ranges.allow(0, kCompute);
  EXPECT_EQ(ranges.rangesFor(QueueClass::AsyncCompute), (std::vector<Span>{{0, 100}}));
  EXPECT_EQ(ranges.allocate(100, 1, kCompute, previous), 0u);
  EXPECT_EQ(previous, std::vector<uint32_t>{0});
  EXPECT_TRUE(ranges.rangesFor(QueueClass::Graphics).empty());  // taken for every queue
}

TYPED_TEST(FreeRangesTest, AllowReachesOnlyWhatIsLeftOfThatOccupant) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(2, 100, heap);
  ranges.release(0, kGraphics);
  ranges.release(1, kGraphics);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(50, 1, kGraphics, previous), 0u);  // best fit: the first, lowest offset
  ranges.allow(0, kCompute);
  EXPECT_EQ(ranges.rangesFor(QueueClass::AsyncCompute), (std::vector<Span>{{50, 100}}));
}

TYPED_TEST(FreeRangesTest, GrowsFromAFreeRangeAtTheTopAndAlignsWithFreePadding) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(2, 100, heap);
  ranges.release(1, kGraphics);
  std::vector<uint32_t> previous;
  // 150 bytes: no range holds them, the top one [100, 200) is extended.
  EXPECT_EQ(ranges.allocate(150, 1, kGraphics, previous), 100u);
  EXPECT_EQ(previous, std::vector<uint32_t>{1});
  EXPECT_EQ(heap, 250u);
  // Aligned to 256: padding [250, 256) is free for both queues and has no last user.
  previous.clear();
  EXPECT_EQ(ranges.allocate(10, 256, kCompute, previous), 256u);
  EXPECT_TRUE(previous.empty());
  EXPECT_EQ(heap, 266u);
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{250, 256}}));
  EXPECT_EQ(ranges.rangesFor(QueueClass::AsyncCompute), (std::vector<Span>{{250, 256}}));
}

// The walk jumps from run to run: a run ending at the top counts only if its
// last fragment is one the queue may take.
TYPED_TEST(FreeRangesTest, GrowsFromTheTopOnlyThroughARangeTheQueueMayTake) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(3, 100, heap);
  ranges.release(1, kGraphics);
  ranges.release(2, kCompute);  // the top: async compute's only
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(150, 1, kGraphics, previous), 300u) << "graphics may not extend [200, 300)";
  EXPECT_TRUE(previous.empty());
  EXPECT_EQ(heap, 450u);
  ranges.allow(2, kGraphics);  // now [100, 300) is one range for graphics, but not at the top
  EXPECT_EQ(ranges.allocate(200, 1, kGraphics, previous), 100u);
  EXPECT_EQ(previous, (std::vector<uint32_t>{1, 2}));
}

TYPED_TEST(FreeRangesTest, AlignmentDecidesWhichRangeFits) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(4, 100, heap);
  ranges.release(1, kGraphics);
  ranges.release(3, kGraphics);
  std::vector<uint32_t> previous;
  // 80 bytes at 128 would overrun [100, 200) and at 384 [300, 400): the heap grows from the top range.
  EXPECT_EQ(ranges.allocate(80, 128, kGraphics, previous), 384u);
  EXPECT_EQ(heap, 464u);
  EXPECT_EQ(ranges.allocate(72, 128, kGraphics, previous), 128u);  // ends at 200 exactly
}

TYPED_TEST(FreeRangesTest, SeveralOrNoQueuesAlwaysGrow) {
  uint64_t heap = 0;
  auto ranges = filled<TypeParam>(1, 100, heap);
  ranges.release(0, kBoth);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(100, 1, kBoth, previous), 100u);
  EXPECT_EQ(ranges.allocate(100, 1, QueueMask::None, previous), 200u);
  EXPECT_TRUE(previous.empty());
}

// Random releases, allowances and allocations: every allocation is the best
// fit over rangesFor(queue) (smallest, then lowest offset), or the top of the heap.
TYPED_TEST(FreeRangesTest, AllocationsAreTheBestFitOfWhatTheQueueMayTake) {
  std::mt19937 rng(7);
  uint64_t heap = 0;
  TestHeap<TypeParam> ranges{.ranges = {}, .size = heap, .blocks = {}};
  ranges.ranges.clear(kBoth);
  struct Live {
    uint64_t offset, size;
    uint32_t id;
  };
  std::vector<Live> live;
  std::vector<Live> released;
  std::vector<uint32_t> previous;
  uint32_t next = 0;
  for (int step = 0; step < 3000; ++step) {
    const uint32_t what = rng() % 4;
    if (what == 0 && !live.empty()) {
      const std::size_t i = rng() % live.size();
      ranges.release(live[i].id, rng() % 2 ? kGraphics : kCompute);
      released.push_back(live[i]);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
      ASSERT_TRUE(consistent(ranges.ranges, heap)) << "step " << step;
    } else if (what == 1 && !released.empty()) {
      const Live& r = released[rng() % released.size()];
      ranges.allow(r.id, kBoth);
      ASSERT_TRUE(consistent(ranges.ranges, heap)) << "step " << step;
    } else {
      const QueueClass queue = rng() % 3 ? QueueClass::Graphics : QueueClass::AsyncCompute;
      const uint64_t size = 16 * (1 + rng() % 20);
      const uint64_t alignment = uint64_t{16} << (rng() % 3);
      const std::vector<Span> free = ranges.rangesFor(queue);
      uint64_t expected = ~uint64_t{0}, bestLength = ~uint64_t{0};
      for (const Span& s : free) {
        const uint64_t at = (s.begin + alignment - 1) / alignment * alignment;
        if (at + size <= s.end && s.end - s.begin < bestLength) {
          expected = at;
          bestLength = s.end - s.begin;
        }
      }
      if (expected == ~uint64_t{0}) {
        const uint64_t start = !free.empty() && free.back().end == heap ? free.back().begin : heap;
        expected = (start + alignment - 1) / alignment * alignment;
      }
      const uint64_t heapBefore = heap;
      previous.clear();
      ASSERT_EQ(ranges.allocate(size, alignment, toMask(queue), previous), expected) << "step " << step;
      ASSERT_EQ(ranges.blocks.size(), next + 1);
      ASSERT_TRUE(consistent(ranges.ranges, heap)) << "step " << step;
      EXPECT_EQ(heap, std::max(heapBefore, expected + size));
      // What was taken is free for nobody now.
      for (const QueueClass q : {QueueClass::Graphics, QueueClass::AsyncCompute}) {
        for (const Span& s : ranges.rangesFor(q)) EXPECT_TRUE(s.end <= expected || s.begin >= expected + size);
      }
      live.push_back({expected, size, next++});
      released.erase(std::remove_if(released.begin(), released.end(),
                                    [&](const Live& r) { return r.offset < expected + size && expected < r.offset + r.size; }),
                     released.end());
    }
  }
}

// placeTransients() gives LinearFreeRanges ranges of any size, zero bytes
// included (an empty fragment joins both its neighbours): its stretches of
// adjacent fragments stay those of the fragments, and what it hands out
// never overlaps what is in use.
TEST(LinearFreeRanges, ZeroByteRangesKeepTheStretchesRight) {
  std::mt19937 rng(11);
  LinearFreeRanges ranges;
  ranges.clear(kBoth);
  uint64_t heap = 0;
  struct Live {
    uint64_t offset, size;
    uint32_t id;
  };
  std::vector<Live> live, released;
  std::vector<uint32_t> previous;
  uint32_t next = 0;
  for (int step = 0; step < 2000; ++step) {
    const uint32_t what = rng() % 4;
    if (what == 0 && !live.empty()) {
      const std::size_t i = rng() % live.size();
      ranges.release(live[i].offset, live[i].size, live[i].id, rng() % 2 ? kGraphics : kCompute);
      released.push_back(live[i]);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
    } else if (what == 1 && !released.empty()) {
      const Live& r = released[rng() % released.size()];
      ranges.allow(r.offset, r.size, r.id, kBoth);
    } else {
      const uint64_t size = rng() % 4 == 0 ? 0 : 16 * (1 + rng() % 8);
      previous.clear();
      const uint64_t offset = ranges.allocate(size, 16, rng() % 2 ? kGraphics : kCompute, heap, previous);
      for (const Live& l : live) {
        ASSERT_TRUE(size == 0 || l.size == 0 || offset + size <= l.offset || l.offset + l.size <= offset)
            << "step " << step;
      }
      live.push_back({offset, size, next++});
      released.erase(std::remove_if(released.begin(), released.end(),
                                    [&](const Live& r) { return r.offset < offset + size && offset < r.offset + r.size; }),
                     released.end());
    }
    ASSERT_TRUE(ranges.consistent()) << "step " << step;
  }
}

// The block list with its size-class bins against the linear walk it
// replaced: transients with random lifetimes, sizes (1 byte to 64 MiB),
// alignments (powers of two and not) and queues (three, a transient's memory
// given back to its own queue at once and to the others later, as placement
// does) must get the same offsets, heap sizes, previous occupants and free
// ranges, allocation by allocation, heap after heap (one FreeRanges reused).
TEST(FreeRanges, PlacesExactlyAsTheLinearWalkOnRandomLifetimes) {
  std::mt19937 rng(2026);
  FreeRanges blocks;
  LinearFreeRanges linear;
  constexpr QueueClass kAll[] = {QueueClass::Graphics, QueueClass::AsyncCompute, QueueClass::Transfer};
  uint64_t heapsCompared = 0, takeOvers = 0;
  for (int heapIndex = 0; heapIndex < 60; ++heapIndex) {
    const uint32_t count = 20 + static_cast<uint32_t>(rng() % 400);
    const uint32_t positions = 10 + count / (1 + rng() % 4);
    const QueueMask used = heapIndex % 3 == 0 ? QueueMask::Graphics | QueueMask::AsyncCompute | QueueMask::Transfer
                                              : kBoth;
    struct Transient {
      uint32_t first, last;
      uint64_t size, alignment;
      QueueMask queues;
      QueueMask taker;
    };
    std::vector<Transient> transients(count);
    for (Transient& t : transients) {
      t.first = static_cast<uint32_t>(rng() % positions);
      t.last = t.first + static_cast<uint32_t>(rng() % (rng() % 4 == 0 ? positions : 6));
      const uint32_t sizeKind = rng() % 4;
      t.size = sizeKind == 0 ? 1 + rng() % 64 : sizeKind == 1 ? 1 + rng() % 4096 : (1 + rng() % 1024) * 65536;
      const uint32_t alignKind = rng() % 8;
      t.alignment = alignKind == 0 ? 1 : alignKind == 1 ? 3 + rng() % 200 : uint64_t{1} << (rng() % 17);
      const QueueClass q = kAll[rng() % (any(used & QueueMask::Transfer) ? 3 : 2)];
      t.taker = rng() % 16 == 0 ? QueueMask::None : toMask(q);  // none: placement could not tell
      t.queues = toMask(q);
      if (rng() % 5 == 0) t.queues |= toMask(kAll[rng() % 2]);
    }
    blocks.clear(used);
    linear.clear(used);
    uint64_t heapA = 0, heapB = 0;
    std::vector<uint32_t> blockOf(count, 0), linearBlockOf(count, 0);
    std::vector<uint32_t> prevA, prevB;
    struct Later {
      uint32_t position, index;
      QueueMask queues;
    };
    std::vector<Later> later;
    std::vector<bool> placed(count, false), done(count, false);
    for (uint32_t p = 0; p <= positions + 8; ++p) {
      // Memory whose last use is behind: to its own queues now, to the others later (or never).
      for (uint32_t i = 0; i < count; ++i) {
        if (!placed[i] || done[i] || transients[i].last >= p) continue;
        done[i] = true;
        const QueueMask now = transients[i].queues & (rng() % 4 ? ~QueueMask::None : QueueMask::None);
        blocks.release(blockOf[i], i, now);
        linear.release(linearBlockOf[i], i, now);
        const QueueMask rest = used & ~now;
        if (any(rest) && rng() % 3) later.push_back({p + 1 + static_cast<uint32_t>(rng() % 5), i, rest});
      }
      for (const Later& l : later) {
        if (l.position != p) continue;
        blocks.allow(l.index, l.queues);
        linear.allow(l.index, l.queues);
      }
      for (uint32_t i = 0; i < count; ++i) {
        const Transient& t = transients[i];
        if (t.first != p) continue;
        prevA.clear();
        prevB.clear();
        const uint64_t a = blocks.allocate(t.size, t.alignment, t.taker, heapA, prevA, blockOf[i]);
        const uint64_t b = linear.allocate(t.size, t.alignment, t.taker, heapB, prevB, linearBlockOf[i]);
        ASSERT_EQ(a, b) << "heap " << heapIndex << ", transient " << i;
        ASSERT_EQ(heapA, heapB) << "heap " << heapIndex << ", transient " << i;
        ASSERT_EQ(prevA, prevB) << "heap " << heapIndex << ", transient " << i;
        ASSERT_TRUE(blocks.consistent(heapA)) << "heap " << heapIndex << ", transient " << i;
        ASSERT_TRUE(linear.consistent()) << "heap " << heapIndex << ", transient " << i;
        takeOvers += prevA.empty() ? 0 : 1;
        placed[i] = true;
      }
      ASSERT_TRUE(linear.consistent()) << "heap " << heapIndex << ", position " << p;
      if (p % 7 == 0) {
        for (const QueueClass q : kAll) ASSERT_EQ(blocks.rangesFor(q), linear.rangesFor(q)) << "heap " << heapIndex;
        ASSERT_EQ(blocks.fragmentCount(), linear.fragmentCount());
      }
    }
    ++heapsCompared;
  }
  EXPECT_EQ(heapsCompared, 60u);
  EXPECT_GT(takeOvers, 1000u) << "the lifetimes must make memory change hands";
}

}  // namespace
}  // namespace sg::graph
