// The shadel-space allocator: levels, exclusivity, reuse, exhaustion.
#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/shadel_gpu_tables.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>

namespace sg::shadel {
namespace {

uint64_t mortonOf(glm::uvec2 p) {
  uint64_t m = 0;
  for (uint32_t bit = 0; bit < 32; ++bit)
    m |= (uint64_t{(p.x >> bit) & 1u} << (2 * bit)) | (uint64_t{(p.y >> bit) & 1u} << (2 * bit + 1));
  return m;
}

// Level blocks are aligned power-of-two squares, so two overlap exactly when
// their Morton-code intervals do: sort and compare neighbours. Cheap enough
// to run after every step.
::testing::AssertionResult noOverlappingBlocks(const ShadelSpace& space) {
  struct Interval {
    uint64_t begin, end;
    uint32_t id;
  };
  std::vector<Interval> intervals;
  for (const auto& [id, instance] : space.instances())
    for (const QuadtreeAllocator::Block& block : instance.blocks) {
      const uint64_t begin = mortonOf(block.origin);
      intervals.push_back({begin, begin + (uint64_t{1} << (2 * block.sizeLog2)), id});
    }
  std::sort(intervals.begin(), intervals.end(), [](const Interval& a, const Interval& b) { return a.begin < b.begin; });
  for (size_t i = 1; i < intervals.size(); ++i)
    if (intervals[i].begin < intervals[i - 1].end)
      return ::testing::AssertionFailure() << "instances " << intervals[i - 1].id << " and " << intervals[i].id
                                           << " overlap";
  return ::testing::AssertionSuccess();
}

// The instance's level blocks against every other instance's: what each
// allocation must guarantee.
::testing::AssertionResult disjointFromOthers(const ShadelSpace& space, uint32_t id) {
  const InstanceShadels& fresh = *space.find(id);
  for (const auto& [otherId, other] : space.instances()) {
    if (otherId == id) continue;
    for (const QuadtreeAllocator::Block& a : fresh.blocks)
      for (const QuadtreeAllocator::Block& b : other.blocks) {
        const glm::uvec2 aEnd = a.origin + (1u << a.sizeLog2), bEnd = b.origin + (1u << b.sizeLog2);
        if (a.origin.x < bEnd.x && b.origin.x < aEnd.x && a.origin.y < bEnd.y && b.origin.y < aEnd.y)
          return ::testing::AssertionFailure() << "instance " << id << " overlaps " << otherId;
      }
  }
  return ::testing::AssertionSuccess();
}

// Every instance's ownedEntries(), all together: fails on any entry owned
// twice or lying outside the sheet.
::testing::AssertionResult noSharedEntries(const ShadelSpace& space) {
  std::vector<uint64_t> owned;  // entry << 32 | instance
  for (const auto& [id, instance] : space.instances()) {
    const std::vector<uint32_t> entries = space.ownedEntries(id);
    if (entries.size() != instance.entryCount())
      return ::testing::AssertionFailure() << "instance " << id << ": entry list size " << entries.size();
    for (uint32_t entry : entries) {
      if (entry >= space.geometry().entryCount()) return ::testing::AssertionFailure() << "entry outside the sheet";
      owned.push_back((uint64_t{entry} << 32) | id);
    }
  }
  std::sort(owned.begin(), owned.end());
  for (size_t i = 1; i < owned.size(); ++i)
    if ((owned[i] >> 32) == (owned[i - 1] >> 32))
      return ::testing::AssertionFailure() << "entry " << (owned[i] >> 32) << " owned by " << (owned[i - 1] & 0xFFFFFFFFu)
                                           << " and " << (owned[i] & 0xFFFFFFFFu);
  if (owned.size() != space.allocatedEntries())
    return ::testing::AssertionFailure() << owned.size() << " owned entries but allocator says "
                                         << space.allocatedEntries();
  return ::testing::AssertionSuccess();
}

TEST(ShadelSpace, LevelsAreAHalvingChainSnappedToOneEntry) {
  ShadelSpace space;
  const DetailLevels levels = makeDetailLevels(2048);
  ASSERT_EQ(levels.levelCount, 9u);  // 2048 .. 8
  const AllocationResult result = space.allocate(3, levels);
  ASSERT_TRUE(result.ok()) << result.message;
  const InstanceShadels& instance = *result.instance;
  ASSERT_EQ(instance.rects.size(), 9u);
  for (uint32_t level = 0; level < 9; ++level) {
    const LevelRect& rect = instance.rects[level];
    EXPECT_EQ(rect.size, 2048u >> level);
    EXPECT_EQ(rect.allocatedSize, std::max(2048u >> level, 64u)) << "level " << level;
    EXPECT_EQ(rect.origin.x % 64, 0u);
    EXPECT_EQ(rect.origin.y % 64, 0u);
    EXPECT_LE(rect.origin.x + rect.allocatedSize, space.geometry().size());
  }
  // 32² + 16² + 8² + 4² + 2² + 4 x 1 entries.
  EXPECT_EQ(instance.entryCount(), 1024u + 256 + 64 + 16 + 4 + 4);
  EXPECT_EQ(space.allocatedEntries(), instance.entryCount());
  EXPECT_TRUE(noSharedEntries(space));
}

TEST(ShadelSpace, RandomAllocFreeNeverShares) {
  for (uint32_t sheetLog2 : {16u, 19u}) {
    SCOPED_TRACE("sheet 2^" + std::to_string(sheetLog2));
    ShadelSpace space({sheetLog2});
    std::mt19937_64 rng(1234 + sheetLog2);
    std::vector<uint32_t> live;
    uint32_t nextId = 0, failures = 0;
    for (int step = 0; step < 3000; ++step) {
      if (!live.empty() && rng() % 3 == 0) {
        const size_t pick = rng() % live.size();
        ASSERT_TRUE(space.release(live[pick]));
        live.erase(live.begin() + static_cast<std::ptrdiff_t>(pick));
      } else {
        const uint32_t level0 = 64u << (rng() % 8);  // 64 .. 8192
        const AllocationResult result = space.allocate(nextId, makeDetailLevels(level0));
        if (result.ok()) {
          ASSERT_TRUE(disjointFromOthers(space, nextId)) << "step " << step;
          live.push_back(nextId);
        } else {
          ASSERT_EQ(result.error, AllocationError::OutOfSpace) << result.message;
          ++failures;
        }
        ++nextId;
      }
      if (step % 50 == 0) {
        ASSERT_TRUE(noOverlappingBlocks(space)) << "step " << step;
      }
      // Entry by entry too (slower: millions of entries on the 512K sheet).
      if (sheetLog2 == 16 && step % 1000 == 999) {
        ASSERT_TRUE(noSharedEntries(space)) << "step " << step;
      }
    }
    EXPECT_TRUE(noSharedEntries(space));
    for (uint32_t id : live) ASSERT_TRUE(space.release(id));
    EXPECT_EQ(space.allocatedEntries(), 0u);
    EXPECT_EQ(space.freeEntries(), space.geometry().entryCount()) << "every buddy merged back";
    // After all that churn the whole sheet is one free block again: the
    // largest possible instance fits.
    const uint32_t largest = space.geometry().size() / 2;
    EXPECT_TRUE(space.allocate(1, makeDetailLevels(largest)).ok());
    if (sheetLog2 == 16) {
      EXPECT_GT(failures, 0u) << "the 64K sheet should have filled up at times";
    }
  }
}

TEST(ShadelSpace, ExhaustionIsReportedAndLeavesNothingBehind) {
  ShadelSpace space;  // 64K: room for two 32K level-0 chains (each takes 1 + 1/4 + ... of a quadrant)
  const DetailLevels huge = makeDetailLevels(32768);
  ASSERT_TRUE(space.allocate(0, huge).ok());
  ASSERT_TRUE(space.allocate(1, huge).ok());
  const uint64_t freeBefore = space.freeEntries();
  const uint64_t generationBefore = space.generation();
  const AllocationResult third = space.allocate(2, huge);
  EXPECT_FALSE(third.ok());
  EXPECT_EQ(third.error, AllocationError::OutOfSpace);
  EXPECT_EQ(third.instance, nullptr);
  EXPECT_NE(third.message.find("instance 2"), std::string::npos) << third.message;
  EXPECT_EQ(space.freeEntries(), freeBefore) << "a failed allocation takes nothing";
  EXPECT_EQ(space.generation(), generationBefore);
  EXPECT_EQ(space.find(2), nullptr);
  // Smaller instances still fit in what is left.
  EXPECT_TRUE(space.allocate(3, makeDetailLevels(4096)).ok());
  EXPECT_TRUE(noSharedEntries(space));
}

TEST(ShadelSpace, FreeMakesSpaceReusable) {
  ShadelSpace space;
  const DetailLevels big = makeDetailLevels(16384);
  uint32_t count = 0;
  while (space.allocate(count, big).ok()) ++count;
  ASSERT_GE(count, 8u);
  EXPECT_FALSE(space.allocate(100, big).ok());
  ASSERT_TRUE(space.release(count / 2));
  EXPECT_FALSE(space.release(count / 2)) << "released twice";
  const AllocationResult again = space.allocate(100, big);
  ASSERT_TRUE(again.ok()) << again.message;
  EXPECT_TRUE(noSharedEntries(space));
}

TEST(ShadelSpace, RejectsBadRequests) {
  ShadelSpace space;
  ASSERT_TRUE(space.allocate(5, makeDetailLevels(256)).ok());
  EXPECT_EQ(space.allocate(5, makeDetailLevels(256)).error, AllocationError::DuplicateInstance);
  EXPECT_EQ(space.allocate(kNoInstance, makeDetailLevels(256)).error, AllocationError::InvalidInstanceId);
  EXPECT_EQ(space.allocate(kMaxInstanceId + 1, makeDetailLevels(256)).error, AllocationError::InvalidInstanceId);
  EXPECT_EQ(space.allocate(6, makeDetailLevels(300)).error, AllocationError::InvalidLevels);
  EXPECT_EQ(space.allocate(6, DetailLevels{256, 0}).error, AllocationError::InvalidLevels);
  EXPECT_EQ(space.allocate(6, makeDetailLevels(1u << 17)).error, AllocationError::OutOfSpace)
      << "a level 0 as large as the sheet leaves no room for level 1";
  EXPECT_THROW(ShadelSpace({15}), std::invalid_argument);
  EXPECT_THROW(ShadelSpace({20}), std::invalid_argument);
}

TEST(ShadelSpace, GpuTablesListEveryOwnedEntryOnce) {
  ShadelSpace space;
  ASSERT_TRUE(space.allocate(0, makeDetailLevels(1024)).ok());
  ASSERT_TRUE(space.allocate(4, makeDetailLevels(256)).ok());
  const ShadelGpuTables tables = buildGpuTables(space);
  EXPECT_EQ(tables.generation, space.generation());
  ASSERT_EQ(tables.instances.size(), 5u);
  EXPECT_EQ(tables.instances[1].levelCount, 0u) << "ids without space have no levels";
  EXPECT_EQ(tables.ownedEntries.size(), space.allocatedEntries());
  for (uint32_t id : {0u, 4u}) {
    const GpuShadelInstance& record = tables.instances[id];
    const InstanceShadels& instance = *space.find(id);
    EXPECT_EQ(record.levelCount, instance.levels.levelCount);
    EXPECT_EQ(record.level0Size, instance.levels.level0Size);
    for (uint32_t level = 0; level < record.levelCount; ++level)
      EXPECT_EQ(tables.levelRects[record.firstLevelRect + level], instance.rects[level]);
    const std::vector<uint32_t> owned = space.ownedEntries(id);
    for (size_t i = 0; i < owned.size(); ++i) {
      const OwnedEntry& entry = tables.ownedEntries[record.firstOwnedEntry + i];
      EXPECT_EQ(entry.entryIndex, owned[i]);
      EXPECT_EQ(entry.instanceId, id);
      // The entry lies in its level's rectangle.
      const LevelRect& rect = instance.rects[entry.level];
      const glm::uvec2 shadel = virtualShadelOf({entry.entryIndex, 0, 0}, space.geometry().entriesPerSideLog2());
      EXPECT_GE(shadel.x, rect.origin.x);
      EXPECT_LT(shadel.x, rect.origin.x + rect.allocatedSize);
      EXPECT_GE(shadel.y, rect.origin.y);
      EXPECT_LT(shadel.y, rect.origin.y + rect.allocatedSize);
    }
  }
}

TEST(QuadtreeAllocator, SplitsAndMergesBuddies) {
  QuadtreeAllocator allocator(4);  // 16 x 16 cells
  const auto a = allocator.allocate(0);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->origin, glm::uvec2(0, 0));
  const auto b = allocator.allocate(0);
  EXPECT_EQ(b->origin, glm::uvec2(1, 0)) << "Morton order: the next buddy";
  const auto c = allocator.allocate(3);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->origin, glm::uvec2(8, 0));
  EXPECT_EQ(allocator.freeCells(), 256u - 2 - 64);
  EXPECT_EQ(allocator.largestFreeBlockLog2(), 3u);
  EXPECT_FALSE(allocator.allocate(5));
  EXPECT_TRUE(allocator.release(*a));
  EXPECT_TRUE(allocator.release(*b));
  EXPECT_TRUE(allocator.release(*c));
  EXPECT_EQ(allocator.freeCells(), 256u);
  EXPECT_EQ(allocator.largestFreeBlockLog2(), 4u);
  EXPECT_FALSE(allocator.release(*c)) << "double release is refused, not double counted";
  EXPECT_FALSE(allocator.release({{3, 0}, 0})) << "never allocated";
  EXPECT_EQ(allocator.freeCells(), 256u);
}

}  // namespace
}  // namespace sg::shadel
