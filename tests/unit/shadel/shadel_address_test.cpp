// Virtual shadel addressing against a brute-force model, and storage sizing.
#include <map>
#include <random>
#include <set>
#include <unordered_map>
#include <vector>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/shadel_address.hpp>
#include <shadelgraph/shadel/shadel_storage.hpp>

namespace sg::shadel {
namespace {

using ChunkKey = std::pair<uint32_t, uint32_t>;  // virtual chunk coordinate (x, y)

// A random sparse remap table: `entries` distinct entries with random
// occupancy (some empty, some full, most in between), storage assigned in
// the order the entries are visited, as shadel-allocate might. The model is
// a map from every marked virtual chunk to its physical chunk, built by
// handing out chunk numbers one by one: no popcount anywhere.
struct RandomSheet {
  SheetGeometry geometry;
  std::unordered_map<uint32_t, RemapEntry> remap;  // sparse: entry index -> entry
  std::map<ChunkKey, uint32_t> model;              // virtual chunk -> physical chunk
  std::vector<uint32_t> entryIndices;

  RandomSheet(uint32_t sizeLog2, size_t entries, std::mt19937_64& rng) : geometry{sizeLog2} {
    const uint32_t perSide = geometry.entriesPerSide();
    std::uniform_int_distribution<uint32_t> coordinate(0, perSide - 1);
    uint32_t nextChunk = 17;  // not zero, so an off-by-base bug shows
    while (entryIndices.size() < entries) {
      const uint32_t ex = coordinate(rng), ey = coordinate(rng);
      const uint32_t index = ey * perSide + ex;
      if (remap.count(index)) continue;
      RemapEntry entry;
      entry.objectInstanceId = static_cast<uint32_t>(entryIndices.size());
      switch (rng() % 8) {
        case 0: entry.occupancy = 0; break;
        case 1: entry.occupancy = ~uint64_t{0}; break;
        case 2: entry.occupancy = uint64_t{1} << (rng() % 64); break;
        case 3: entry.occupancy = rng() & rng() & rng(); break;  // sparse
        default: entry.occupancy = rng(); break;
      }
      // One in ten marked entries got no storage (partition overflow).
      const bool overflowed = entry.occupancy != 0 && rng() % 10 == 0;
      if (entry.occupancy != 0 && !overflowed) {
        entry.storageBase = nextChunk;
        for (uint32_t chunk = 0; chunk < 64; ++chunk)
          if ((entry.occupancy >> chunk) & 1u) model[{ex * 8 + chunk % 8, ey * 8 + chunk / 8}] = nextChunk++;
        nextChunk += static_cast<uint32_t>(rng() % 5);  // partitions leave gaps
      }
      remap[index] = entry;
      entryIndices.push_back(index);
    }
  }

  uint32_t expected(glm::uvec2 shadel) const {
    const auto it = model.find({shadel.x / 8, shadel.y / 8});
    return it == model.end() ? kInvalidChunk : it->second;
  }
  uint32_t lookup(glm::uvec2 shadel) const {
    const ShadelAddress address = addressOf(shadel, geometry.entriesPerSideLog2());
    const auto it = remap.find(address.entryIndex);
    return it == remap.end() ? kInvalidChunk : physicalChunk(it->second, address.chunkIndex);
  }
  // A shadel inside a random populated entry (or anywhere, one time in five).
  glm::uvec2 randomShadel(std::mt19937_64& rng) const {
    if (rng() % 5 == 0) return {rng() % geometry.size(), rng() % geometry.size()};
    const uint32_t index = entryIndices[rng() % entryIndices.size()];
    const uint32_t ex = index % geometry.entriesPerSide(), ey = index / geometry.entriesPerSide();
    return {ex * 64 + rng() % 64, ey * 64 + rng() % 64};
  }
};

class AddressingBySheetSize : public ::testing::TestWithParam<uint32_t> {};

TEST_P(AddressingBySheetSize, MatchesSequentialAllocationModel) {
  std::mt19937_64 rng(20220517 + GetParam());
  const RandomSheet sheet(GetParam(), 3000, rng);
  size_t valid = 0;
  for (int i = 0; i < 200000; ++i) {
    const glm::uvec2 shadel = sheet.randomShadel(rng);
    const uint32_t expected = sheet.expected(shadel);
    ASSERT_EQ(sheet.lookup(shadel), expected) << "shadel (" << shadel.x << ", " << shadel.y << ")";
    valid += expected != kInvalidChunk;
  }
  EXPECT_GT(valid, 50000u) << "the random cases must mostly hit marked chunks";
  // Every marked chunk, exhaustively, at all 64 of its shadels' corners and centre.
  for (const auto& [chunk, physical] : sheet.model)
    for (glm::uvec2 texel : {glm::uvec2(0, 0), glm::uvec2(7, 0), glm::uvec2(0, 7), glm::uvec2(7, 7), glm::uvec2(3, 4)})
      ASSERT_EQ(sheet.lookup(glm::uvec2(chunk.first, chunk.second) * 8u + texel), physical);
}

TEST_P(AddressingBySheetSize, InverseRoundTrips) {
  std::mt19937_64 rng(7 + GetParam());
  const SheetGeometry geometry{GetParam()};
  const uint32_t log2 = geometry.entriesPerSideLog2();
  for (int i = 0; i < 100000; ++i) {
    const glm::uvec2 shadel(rng() % geometry.size(), rng() % geometry.size());
    const ShadelAddress address = addressOf(shadel, log2);
    ASSERT_LT(address.entryIndex, geometry.entryCount());
    ASSERT_LT(address.chunkIndex, 64u);
    ASSERT_LT(address.texelIndex, 64u);
    ASSERT_EQ(virtualShadelOf(address, log2), shadel);
    const ShadelAddress random{static_cast<uint32_t>(rng() % geometry.entryCount()), static_cast<uint32_t>(rng() % 64),
                               static_cast<uint32_t>(rng() % 64)};
    ASSERT_EQ(addressOf(virtualShadelOf(random, log2), log2), random);
  }
  // The extreme corner of the sheet.
  const glm::uvec2 last(geometry.size() - 1);
  EXPECT_EQ(addressOf(last, log2), (ShadelAddress{static_cast<uint32_t>(geometry.entryCount() - 1), 63, 63}));
}

INSTANTIATE_TEST_SUITE_P(Sheets, AddressingBySheetSize, ::testing::Values(16u, 19u),
                         [](const auto& param) { return std::to_string(1u << (param.param - 10)) + "K"; });

TEST(ShadelAddress, KnownValues) {
  const uint32_t log2 = SheetGeometry{16}.entriesPerSideLog2();  // 1024 entries a side
  EXPECT_EQ(log2, 10u);
  EXPECT_EQ(addressOf({0, 0}, log2), (ShadelAddress{0, 0, 0}));
  EXPECT_EQ(addressOf({9, 0}, log2), (ShadelAddress{0, 1, 1}));
  EXPECT_EQ(addressOf({63, 63}, log2), (ShadelAddress{0, 63, 63}));
  EXPECT_EQ(addressOf({64, 0}, log2), (ShadelAddress{1, 0, 0}));
  EXPECT_EQ(addressOf({64 * 5 + 17, 64 * 3 + 42}, log2), (ShadelAddress{3 * 1024 + 5, 5 * 8 + 2, 2 * 8 + 1}));
}

TEST(ShadelAddress, PhysicalChunkCountsBitsBelow) {
  RemapEntry entry;
  entry.storageBase = 100;
  entry.occupancy = (uint64_t{1} << 0) | (uint64_t{1} << 5) | (uint64_t{1} << 31) | (uint64_t{1} << 32) | (uint64_t{1} << 63);
  EXPECT_EQ(physicalChunk(entry, 0), 100u);
  EXPECT_EQ(physicalChunk(entry, 5), 101u);
  EXPECT_EQ(physicalChunk(entry, 31), 102u);
  EXPECT_EQ(physicalChunk(entry, 32), 103u);
  EXPECT_EQ(physicalChunk(entry, 63), 104u);
  EXPECT_EQ(physicalChunk(entry, 1), kInvalidChunk) << "unmarked";
  entry.storageBase = kNoStorage;
  EXPECT_EQ(physicalChunk(entry, 0), kInvalidChunk) << "marked but not stored (overflow)";
  EXPECT_EQ(chunksBefore(~uint64_t{0}, 63), 63u);
  EXPECT_EQ(chunksBefore(~uint64_t{0}, 0), 0u);
}

TEST(ShadelAddress, DenseTableLookupMatchesSparseModel) {
  std::mt19937_64 rng(99);
  const RandomSheet sheet(16, 500, rng);
  std::vector<RemapEntry> dense(sheet.geometry.entryCount());  // 16 MiB at 64K²
  for (const auto& [index, entry] : sheet.remap) dense[index] = entry;
  for (int i = 0; i < 50000; ++i) {
    const glm::uvec2 shadel = sheet.randomShadel(rng);
    ASSERT_EQ(physicalChunkOf(dense, shadel, sheet.geometry.entriesPerSideLog2()), sheet.expected(shadel));
  }
  EXPECT_EQ(physicalChunkOf(std::span<const RemapEntry>(dense).first(10), {64 * 20, 0}, 10), kInvalidChunk)
      << "an entry past the table's end is a miss, not a read out of bounds";
}

TEST(ShadelStorage, ChunksForOutput) {
  EXPECT_EQ(chunksForOutput(1920, 1080), 64800u);  // 2x the pixels
  EXPECT_EQ(chunksForOutput(1920, 1080, 1.25), 40500u);
  EXPECT_EQ(chunksForOutput(1920, 1080, 1.0), 40500u) << "raised to the trilinear floor";
  EXPECT_EQ(chunksForOutput(3840, 2160, 3.0), 388800u);
  EXPECT_EQ(chunksForOutput(1, 1), 1u);
}

TEST(ShadelStorage, LayoutHoldsEveryChunkAndPartitionsEvenly) {
  for (uint32_t chunks : {1u, 15u, 64800u, 388800u}) {
    const StorageLayout layout = storageLayoutFor(chunks, 16);
    EXPECT_GE(layout.capacityChunks(), chunks);
    EXPECT_LT(layout.capacityChunks(), chunks + layout.counterCount);
    EXPECT_GE(uint64_t{layout.widthChunks} * layout.heightChunks, layout.capacityChunks());
    EXPECT_LE(layout.widthTexels(), 16384u);
    // Every usable chunk's texels and gutter have their own place in the image.
    std::set<std::pair<uint32_t, uint32_t>> seen;
    for (uint32_t c = 0; c < std::min(layout.capacityChunks(), 2000u); ++c) {
      for (uint32_t t : {0u, 9u, 63u}) {
        const glm::uvec2 texel = storageTexel(c, t, layout.widthChunks);
        ASSERT_EQ(texel, storedTexel(c, {t % kChunkSize, t / kChunkSize}, layout.widthChunks));
        ASSERT_TRUE(seen.insert({texel.x, texel.y}).second);
      }
      for (glm::uvec2 gutter : {glm::uvec2(8, 0), glm::uvec2(8, 7), glm::uvec2(0, 8), glm::uvec2(8, 8)}) {
        const glm::uvec2 texel = storedTexel(c, gutter, layout.widthChunks);
        ASSERT_LT(texel.x, layout.widthTexels());
        ASSERT_LT(texel.y, layout.heightTexels());
        ASSERT_TRUE(seen.insert({texel.x, texel.y}).second);
      }
    }
  }
}

TEST(ShadelStorage, CountersSpreadNeighbouringEntries) {
  std::vector<int> histogram(16, 0);
  for (uint32_t entry = 0; entry < 16000; ++entry) ++histogram[storageCounterFor(entry, 16)];
  for (int count : histogram) EXPECT_NEAR(count, 1000, 150);
  EXPECT_EQ(storageCounterFor(12345, 1), 0u);
}

}  // namespace
}  // namespace sg::shadel
