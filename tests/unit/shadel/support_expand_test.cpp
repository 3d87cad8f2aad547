// support-expand's CPU reference (the twin of support_expand.comp): growth to
// the 8-neighbourhood, clipping at the level rectangle, across remap entries,
// no cascade, and objects without support left alone; then random sheets
// against a brute-force chunk-grid model.
#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/support_expand.hpp>

namespace sg::shadel {
namespace {

using Chunk = std::pair<uint32_t, uint32_t>;  // sheet chunk coordinates (x, y)

// A small dense sheet (8x8 entries = 64x64 chunks) with instances of one level each.
struct Sheet {
  static constexpr uint32_t kLog2 = 3;
  static constexpr uint32_t kSideChunks = (1u << kLog2) * kEntryChunks;
  std::vector<RemapEntry> remap = std::vector<RemapEntry>(size_t(1) << (2 * kLog2));
  std::vector<GpuShadelInstance> instances;
  std::vector<LevelRect> rects;
  std::vector<OwnedEntry> owned;
  std::vector<uint32_t> support;

  // origin in shadels (a multiple of 64); allocated: size snapped up to entries.
  uint32_t addInstance(glm::uvec2 origin, uint32_t size, uint32_t supportChunks) {
    const uint32_t id = uint32_t(instances.size());
    const uint32_t allocated = std::max(kEntrySize, (size + kEntrySize - 1) / kEntrySize * kEntrySize);
    instances.push_back({uint32_t(rects.size()), 1, size, uint32_t(owned.size())});
    rects.push_back({origin, size, allocated});
    for (uint32_t y = 0; y < allocated / kEntrySize; ++y)
      for (uint32_t x = 0; x < allocated / kEntrySize; ++x)
        owned.push_back({((origin.y / kEntrySize + y) << kLog2) | (origin.x / kEntrySize + x), id, 0, 0});
    support.push_back(supportChunks);
    return id;
  }
  static std::pair<uint32_t, uint32_t> bitOf(Chunk c) {
    return {((c.second / kEntryChunks) << kLog2) | (c.first / kEntryChunks),
            (c.second % kEntryChunks) * kEntryChunks + c.first % kEntryChunks};
  }
  void mark(Chunk c) {
    const auto [entry, bit] = bitOf(c);
    remap[entry].occupancy |= uint64_t(1) << bit;
  }
  bool isMarked(Chunk c) const {
    const auto [entry, bit] = bitOf(c);
    return (remap[entry].occupancy >> bit) & 1u;
  }
  std::set<Chunk> marked() const {
    std::set<Chunk> chunks;
    for (uint32_t y = 0; y < kSideChunks; ++y)
      for (uint32_t x = 0; x < kSideChunks; ++x)
        if (isMarked({x, y})) chunks.insert({x, y});
    return chunks;
  }
  uint32_t expand() { return expandSupport(remap, {kLog2, instances, rects, owned, support}); }
};

std::set<Chunk> square(uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {  // inclusive
  std::set<Chunk> chunks;
  for (uint32_t y = y0; y <= y1; ++y)
    for (uint32_t x = x0; x <= x1; ++x) chunks.insert({x, y});
  return chunks;
}

TEST(SupportExpand, ChunkSpanCoversPartlyCoveredChunks) {
  EXPECT_EQ(chunkSpanOf({{64, 128}, 128, 128}).begin, glm::uvec2(8, 16));
  EXPECT_EQ(chunkSpanOf({{64, 128}, 128, 128}).end, glm::uvec2(24, 32));
  EXPECT_EQ(chunkSpanOf({{64, 0}, 100, 128}).end, glm::uvec2(21, 13));  // 100 shadels: 12.5 chunks
  EXPECT_EQ(chunkSpanOf({{64, 0}, 4, 64}).end, glm::uvec2(9, 1));       // smaller than a chunk
}

TEST(SupportExpand, SingleMarkedChunkGrowsToThreeByThree) {
  Sheet sheet;
  sheet.addInstance({64, 64}, 128, 1);
  sheet.mark({12, 12});
  EXPECT_EQ(sheet.expand(), 8u);
  EXPECT_EQ(sheet.marked(), square(11, 11, 13, 13));
}

TEST(SupportExpand, RadiusTwoGrowsToFiveByFive) {
  Sheet sheet;
  sheet.addInstance({64, 64}, 128, 2);
  sheet.mark({12, 12});
  EXPECT_EQ(sheet.expand(), 24u);
  EXPECT_EQ(sheet.marked(), square(10, 10, 14, 14));
}

TEST(SupportExpand, ClipsAtTheLevelRectangle) {
  Sheet sheet;
  sheet.addInstance({64, 64}, 128, 1);  // chunks 8..23
  sheet.mark({8, 8});
  sheet.mark({23, 15});
  EXPECT_EQ(sheet.expand(), 3u + 5u);
  std::set<Chunk> expected = square(8, 8, 9, 9);
  expected.merge(square(22, 14, 23, 16));
  EXPECT_EQ(sheet.marked(), expected);
}

TEST(SupportExpand, ClipsAtARectangleNotAMultipleOfEight) {
  Sheet sheet;
  sheet.addInstance({64, 0}, 100, 1);  // chunks 8..20 (chunk 20 is half inside); the entries reach chunk 23
  sheet.mark({20, 12});
  EXPECT_EQ(sheet.expand(), 3u);
  EXPECT_EQ(sheet.marked(), square(19, 11, 20, 12));
}

TEST(SupportExpand, ReachesIntoTheNeighbouringEntries) {
  Sheet sheet;
  sheet.addInstance({64, 64}, 128, 1);  // entries (1,1)..(2,2): chunks 8..15 | 16..23
  sheet.mark({15, 15});                 // the corner of entry (1,1)
  EXPECT_EQ(sheet.expand(), 8u);
  EXPECT_EQ(sheet.marked(), square(14, 14, 16, 16));
  EXPECT_NE(sheet.remap[(2u << 3) | 2u].occupancy, 0u);  // entry (2,2) got chunk (16,16)
}

TEST(SupportExpand, RectangleSmallerThanAChunk) {
  Sheet sheet;
  sheet.addInstance({128, 0}, 4, 1);   // one chunk, (16,0)
  sheet.addInstance({192, 0}, 12, 1);  // two by two chunks, (24..25, 0..1)
  sheet.mark({16, 0});
  sheet.mark({24, 0});
  EXPECT_EQ(sheet.expand(), 3u);
  std::set<Chunk> expected{{16, 0}};
  expected.merge(square(24, 0, 25, 1));
  EXPECT_EQ(sheet.marked(), expected);
}

TEST(SupportExpand, NoCascadeFromAddedChunks) {
  Sheet sheet;
  sheet.addInstance({0, 0}, 256, 1);
  sheet.mark({10, 10});
  sheet.mark({26, 10});  // far enough that the squares do not touch
  EXPECT_EQ(sheet.expand(), 16u);
  std::set<Chunk> expected = square(9, 9, 11, 11);
  expected.merge(square(25, 9, 27, 11));
  EXPECT_EQ(sheet.marked(), expected);
  // A second run grows from what the first added: only a new pass cascades.
  EXPECT_EQ(sheet.expand(), 32u);
  EXPECT_EQ(sheet.marked().size(), 50u);
}

TEST(SupportExpand, InstancesWithoutSupportAndNeighbourInstancesUntouched) {
  Sheet sheet;
  sheet.addInstance({0, 0}, 64, 1);   // chunks 0..7
  sheet.addInstance({64, 0}, 64, 0);  // chunks 8..15, right beside it, no support
  sheet.mark({7, 3});
  sheet.mark({8, 5});
  const uint64_t before = sheet.remap[1].occupancy;
  EXPECT_EQ(sheet.expand(), 5u);
  EXPECT_EQ(sheet.remap[1].occupancy, before);  // neither grown nor grown into
  std::set<Chunk> expected = square(6, 2, 7, 4);
  expected.insert({8, 5});
  EXPECT_EQ(sheet.marked(), expected);
}

// Random sheets of several instances (some without support, some with sizes
// not a multiple of 8) against a model on the chunk grid.
TEST(SupportExpand, RandomSheetsMatchTheChunkGridModel) {
  std::mt19937 rng(77);
  for (int round = 0; round < 50; ++round) {
    Sheet sheet;
    std::vector<std::pair<ChunkSpan, uint32_t>> spans;  // per instance: chunks, radius
    const uint32_t sizes[] = {4, 8, 12, 64, 100, 128, 200};
    for (uint32_t slot = 0; slot < 4; ++slot) {
      const uint32_t size = sizes[rng() % 7], radius = rng() % 3;
      const glm::uvec2 origin((slot % 2) * 256, (slot / 2) * 256);
      sheet.addInstance(origin, size, radius);
      spans.push_back({chunkSpanOf(sheet.rects.back()), radius});
    }
    for (int i = 0; i < 60; ++i) {
      const auto& [span, radius] = spans[rng() % spans.size()];
      const glm::uvec2 extent = span.end - span.begin;
      sheet.mark({span.begin.x + rng() % extent.x, span.begin.y + rng() % extent.y});
    }
    const std::set<Chunk> original = sheet.marked();
    std::set<Chunk> expected = original;
    for (const auto& [span, radius] : spans)
      for (const auto& [x, y] : original) {
        if (!span.contains(glm::ivec2(x, y))) continue;
        const int r = int(radius);
        for (int dy = -r; dy <= r; ++dy)
          for (int dx = -r; dx <= r; ++dx)
            if (span.contains(glm::ivec2(int(x) + dx, int(y) + dy))) expected.insert({x + dx, y + dy});
      }
    EXPECT_EQ(sheet.expand(), uint32_t(expected.size() - original.size())) << "round " << round;
    EXPECT_EQ(sheet.marked(), expected) << "round " << round;
  }
}

}  // namespace
}  // namespace sg::shadel
