#pragma once
// Physical shadel storage: how much, and how it is laid out.
//
// Sized from the output, not from the virtual sheet: the paper's rule of
// thumb is twice as many shadels as pixels (§3.6); trilinear filtering alone
// needs 1.25x (a pixel uses its level and a quarter-size one), so less than
// that overflows every frame.
#include <cstdint>

#include <shadelgraph/shadel/remap_entry.hpp>

namespace sg::shadel {

inline constexpr double kDefaultStorageFactor = 2.0;
inline constexpr double kMinStorageFactor = 1.25;

// Chunks (8x8 shadels) for a width x height output: ceil(w * h * factor / 64),
// with factor raised to kMinStorageFactor if below it.
uint32_t chunksForOutput(uint32_t width, uint32_t height, double factor = kDefaultStorageFactor);

// A layer image of widthChunks x heightChunks chunk tiles (see storedTexel in
// shadel_address.hpp), split into `counterCount` equal partitions, each
// filled by its own atomic counter in shadel-allocate: partition c starts at
// chunk c * chunksPerCounter. Chunks past counterCount * chunksPerCounter are
// never used.
struct StorageLayout {
  uint32_t widthChunks = 0;
  uint32_t heightChunks = 0;
  uint32_t counterCount = 0;
  uint32_t chunksPerCounter = 0;

  uint32_t capacityChunks() const { return counterCount * chunksPerCounter; }
  uint32_t widthTexels() const { return widthChunks * kStoredChunkSize; }
  uint32_t heightTexels() const { return heightChunks * kStoredChunkSize; }
};

// At least `chunks` usable chunks in an image no wider than maxImageSize
// texels (a power-of-two width near the square root, so the image is about
// square). counterCount is clamped to [1, chunks].
StorageLayout storageLayoutFor(uint32_t chunks, uint32_t counterCount = 16, uint32_t maxImageSize = 16384);

}  // namespace sg::shadel
