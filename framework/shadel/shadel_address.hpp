#pragma once
// Integer addressing in the virtual shadel sheet: virtual shadel coordinate
// -> (remap entry, chunk, texel) -> physical chunk, and back.
//
// Everything is integral: a float UV times a 512K sheet has 1/32-shadel
// precision, so callers turn UVs into level-local integer shadels first (see
// level_selection.hpp) and add the level's integer origin.
// Mirrored line for line by shaders/shadel_address.glsl.
#include <bit>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include <shadelgraph/shadel/remap_entry.hpp>

namespace sg::shadel {

// A square sheet of 2^sizeLog2 shadels a side.
struct SheetGeometry {
  uint32_t sizeLog2 = 16;

  uint32_t size() const { return 1u << sizeLog2; }
  uint32_t entriesPerSideLog2() const { return sizeLog2 - kEntrySizeLog2; }
  uint32_t entriesPerSide() const { return 1u << entriesPerSideLog2(); }
  uint64_t entryCount() const { return uint64_t{entriesPerSide()} * entriesPerSide(); }
};

struct ShadelAddress {
  uint32_t entryIndex = 0;  // entryY * entriesPerSide + entryX
  uint32_t chunkIndex = 0;  // 0..63: chunkY * 8 + chunkX inside the entry; the occupancy bit
  uint32_t texelIndex = 0;  // 0..63: texelY * 8 + texelX inside the chunk

  bool operator==(const ShadelAddress&) const = default;
};

// GLSL: sgShadelAddress.
inline ShadelAddress addressOf(glm::uvec2 shadel, uint32_t entriesPerSideLog2) {
  const glm::uvec2 entry = shadel >> kEntrySizeLog2;
  const glm::uvec2 chunk = (shadel >> kChunkSizeLog2) & (kEntryChunks - 1);
  const glm::uvec2 texel = shadel & (kChunkSize - 1);
  return {(entry.y << entriesPerSideLog2) | entry.x, chunk.y * kEntryChunks + chunk.x, texel.y * kChunkSize + texel.x};
}

// The inverse, used by layer-shade to find the shadel a work item's thread
// stands for. GLSL: sgVirtualShadel.
inline glm::uvec2 virtualShadelOf(const ShadelAddress& address, uint32_t entriesPerSideLog2) {
  const glm::uvec2 entry(address.entryIndex & ((1u << entriesPerSideLog2) - 1), address.entryIndex >> entriesPerSideLog2);
  const glm::uvec2 chunk(address.chunkIndex & (kEntryChunks - 1), address.chunkIndex >> 3);
  const glm::uvec2 texel(address.texelIndex & (kChunkSize - 1), address.texelIndex >> 3);
  return (entry << kEntrySizeLog2) | (chunk << kChunkSizeLog2) | texel;
}

// Marked chunks of the entry that come before chunkIndex: its offset from
// storageBase (the paper's Formula 1). GLSL: sgChunksBefore.
inline uint32_t chunksBefore(uint64_t occupancy, uint32_t chunkIndex) {
  return static_cast<uint32_t>(std::popcount(occupancy & ((uint64_t{1} << chunkIndex) - 1)));
}

// GLSL: sgIsChunkMarked.
inline bool isChunkMarked(uint64_t occupancy, uint32_t chunkIndex) { return (occupancy >> chunkIndex) & 1u; }

// The physical chunk holding chunkIndex of this entry, kInvalidChunk when it
// is not marked or the entry got no storage. GLSL: sgPhysicalChunk.
inline uint32_t physicalChunk(const RemapEntry& entry, uint32_t chunkIndex) {
  if (!isChunkMarked(entry.occupancy, chunkIndex) || entry.storageBase == kNoStorage) return kInvalidChunk;
  return entry.storageBase + chunksBefore(entry.occupancy, chunkIndex);
}

// Whole lookup against a dense remap table (entryCount() entries).
uint32_t physicalChunkOf(std::span<const RemapEntry> remap, glm::uvec2 shadel, uint32_t entriesPerSideLog2);

// Physical storage is a 2D image (one per layer) of widthChunks x heightChunks
// chunk tiles of kStoredChunkSize² texels (the chunk and its gutter), chunk c
// at (c % widthChunks, c / widthChunks). `inTile` in [0, kStoredChunkSize)²:
// texel (x, y) of the tile holds the chunk's shadel (x, y), x or y = 8 the
// gutter. GLSL: sgStoredTexel.
inline glm::uvec2 storedTexel(uint32_t physicalChunkIndex, glm::uvec2 inTile, uint32_t widthChunks) {
  const glm::uvec2 chunk(physicalChunkIndex % widthChunks, physicalChunkIndex / widthChunks);
  return chunk * kStoredChunkSize + inTile;
}

// The texel of shadel texelIndex (row-major 8x8) of a physical chunk. GLSL: sgStorageTexel.
inline glm::uvec2 storageTexel(uint32_t physicalChunkIndex, uint32_t texelIndex, uint32_t widthChunks) {
  return storedTexel(physicalChunkIndex, glm::uvec2(texelIndex & (kChunkSize - 1), texelIndex >> 3), widthChunks);
}

// Which of `counterCount` allocation counters (storage partitions)
// shadel-allocate uses for an entry: a hash, so neighbouring entries, which
// are marked together, spread over the partitions (paper §3.5).
// GLSL: sgStorageCounter.
inline uint32_t storageCounterFor(uint32_t entryIndex, uint32_t counterCount) {
  // lowbias32 (Chris Wellons): good avalanche with 32-bit integer ops only.
  uint32_t h = entryIndex;
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h % counterCount;
}

}  // namespace sg::shadel
