#include <shadelgraph/graph/free_ranges.hpp>

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

// A heap of `count` ranges of `size` bytes back to back, all in use; occupant i at i * size.
FreeRanges filled(uint32_t count, uint64_t size, uint64_t& heapSize) {
  FreeRanges ranges;
  ranges.clear(kBoth);
  std::vector<uint32_t> previous;
  for (uint32_t i = 0; i < count; ++i) EXPECT_EQ(ranges.allocate(size, 1, kGraphics, heapSize, previous), i * size);
  EXPECT_TRUE(previous.empty());
  return ranges;
}

TEST(FreeRanges, BestFitTakesTheSmallestRangeThatHolds) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(6, 100, heap);
  ranges.release(0, 100, 0, kGraphics);    // 100 bytes at 0
  ranges.release(200, 100, 2, kGraphics);  // 200 bytes at 200 (merged with 3)
  ranges.release(300, 100, 3, kGraphics);
  ranges.release(500, 100, 5, kGraphics);  // 100 bytes at 500
  std::vector<uint32_t> previous;
  // 150 bytes fit only in [200, 400); 80 bytes fit anywhere, first of the two smallest.
  EXPECT_EQ(ranges.allocate(150, 1, kGraphics, heap, previous), 200u);
  EXPECT_EQ(previous, (std::vector<uint32_t>{2, 3}));
  previous.clear();
  EXPECT_EQ(ranges.allocate(80, 1, kGraphics, heap, previous), 0u);
  EXPECT_EQ(previous, std::vector<uint32_t>{0});
  EXPECT_EQ(heap, 600u);
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{80, 100}, {350, 400}, {500, 600}}));
}

TEST(FreeRanges, AdjacentRangesMergeForAQueueButKeepTheirLastUsers) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(3, 100, heap);
  ranges.release(100, 100, 1, kGraphics);
  ranges.release(0, 100, 0, kGraphics);
  ranges.release(200, 100, 2, kGraphics);
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{0, 300}}));
  EXPECT_EQ(ranges.fragmentCount(), 3u);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(250, 1, kGraphics, heap, previous), 0u);
  EXPECT_EQ(previous, (std::vector<uint32_t>{0, 1, 2}));  // every user of the bytes taken
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{250, 300}}));
  EXPECT_EQ(heap, 300u);
}

TEST(FreeRanges, AQueueTakesOnlyWhatItIsAllowedTo) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(2, 100, heap);
  ranges.release(0, 100, 0, kGraphics);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(100, 1, kCompute, heap, previous), 200u);  // not allowed: grows
  EXPECT_TRUE(previous.empty());
  ranges.allow(0, 100, 0, kCompute);
  EXPECT_EQ(ranges.rangesFor(QueueClass::AsyncCompute), (std::vector<Span>{{0, 100}}));
  EXPECT_EQ(ranges.allocate(100, 1, kCompute, heap, previous), 0u);
  EXPECT_EQ(previous, std::vector<uint32_t>{0});
  EXPECT_TRUE(ranges.rangesFor(QueueClass::Graphics).empty());  // taken for every queue
}

TEST(FreeRanges, AllowReachesOnlyWhatIsLeftOfThatOccupant) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(2, 100, heap);
  ranges.release(0, 100, 0, kGraphics);
  ranges.release(100, 100, 1, kGraphics);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(50, 1, kGraphics, heap, previous), 0u);  // best fit: the first, lowest offset
  ranges.allow(0, 100, 0, kCompute);
  EXPECT_EQ(ranges.rangesFor(QueueClass::AsyncCompute), (std::vector<Span>{{50, 100}}));
}

TEST(FreeRanges, GrowsFromAFreeRangeAtTheTopAndAlignsWithFreePadding) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(2, 100, heap);
  ranges.release(100, 100, 1, kGraphics);
  std::vector<uint32_t> previous;
  // 150 bytes: no range holds them, the top one [100, 200) is extended.
  EXPECT_EQ(ranges.allocate(150, 1, kGraphics, heap, previous), 100u);
  EXPECT_EQ(previous, std::vector<uint32_t>{1});
  EXPECT_EQ(heap, 250u);
  // Aligned to 256: padding [250, 256) is free for both queues and has no last user.
  previous.clear();
  EXPECT_EQ(ranges.allocate(10, 256, kCompute, heap, previous), 256u);
  EXPECT_TRUE(previous.empty());
  EXPECT_EQ(heap, 266u);
  EXPECT_EQ(ranges.rangesFor(QueueClass::Graphics), (std::vector<Span>{{250, 256}}));
  EXPECT_EQ(ranges.rangesFor(QueueClass::AsyncCompute), (std::vector<Span>{{250, 256}}));
}

// The walk jumps from run to run: a run ending at the top counts only if its
// last fragment is one the queue may take.
TEST(FreeRanges, GrowsFromTheTopOnlyThroughARangeTheQueueMayTake) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(3, 100, heap);
  ranges.release(100, 100, 1, kGraphics);
  ranges.release(200, 100, 2, kCompute);  // the top: async compute's only
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(150, 1, kGraphics, heap, previous), 300u) << "graphics may not extend [200, 300)";
  EXPECT_TRUE(previous.empty());
  EXPECT_EQ(heap, 450u);
  ranges.allow(200, 100, 2, kGraphics);  // now [100, 300) is one range for graphics, but not at the top
  EXPECT_EQ(ranges.allocate(200, 1, kGraphics, heap, previous), 100u);
  EXPECT_EQ(previous, (std::vector<uint32_t>{1, 2}));
}

TEST(FreeRanges, AlignmentDecidesWhichRangeFits) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(4, 100, heap);
  ranges.release(100, 100, 1, kGraphics);
  ranges.release(300, 100, 3, kGraphics);
  std::vector<uint32_t> previous;
  // 80 bytes at 128 would overrun [100, 200) and at 384 [300, 400): the heap grows from the top range.
  EXPECT_EQ(ranges.allocate(80, 128, kGraphics, heap, previous), 384u);
  EXPECT_EQ(heap, 464u);
  EXPECT_EQ(ranges.allocate(72, 128, kGraphics, heap, previous), 128u);  // ends at 200 exactly
}

TEST(FreeRanges, SeveralOrNoQueuesAlwaysGrow) {
  uint64_t heap = 0;
  FreeRanges ranges = filled(1, 100, heap);
  ranges.release(0, 100, 0, kBoth);
  std::vector<uint32_t> previous;
  EXPECT_EQ(ranges.allocate(100, 1, kBoth, heap, previous), 100u);
  EXPECT_EQ(ranges.allocate(100, 1, QueueMask::None, heap, previous), 200u);
  EXPECT_TRUE(previous.empty());
}

// Random releases, allowances and allocations: every allocation is the best
// fit over rangesFor(queue) (smallest, then lowest offset), or the top of the heap.
TEST(FreeRanges, AllocationsAreTheBestFitOfWhatTheQueueMayTake) {
  std::mt19937 rng(7);
  FreeRanges ranges;
  ranges.clear(kBoth);
  uint64_t heap = 0;
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
      ranges.release(live[i].offset, live[i].size, live[i].id, rng() % 2 ? kGraphics : kCompute);
      released.push_back(live[i]);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(i));
    } else if (what == 1 && !released.empty()) {
      const Live& r = released[rng() % released.size()];
      ranges.allow(r.offset, r.size, r.id, kBoth);
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
      ASSERT_EQ(ranges.allocate(size, alignment, toMask(queue), heap, previous), expected) << "step " << step;
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

}  // namespace
}  // namespace sg::graph
