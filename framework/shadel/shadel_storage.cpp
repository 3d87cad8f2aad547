#include <algorithm>
#include <bit>
#include <cmath>

#include <shadelgraph/shadel/shadel_storage.hpp>

namespace sg::shadel {

uint32_t chunksForOutput(uint32_t width, uint32_t height, double factor) {
  const double shadels = static_cast<double>(width) * static_cast<double>(height) * std::max(factor, kMinStorageFactor);
  return static_cast<uint32_t>(std::ceil(shadels / 64.0));
}

StorageLayout storageLayoutFor(uint32_t chunks, uint32_t counterCount, uint32_t maxImageSize) {
  StorageLayout layout;
  chunks = std::max(chunks, 1u);
  layout.counterCount = std::clamp(counterCount, 1u, chunks);
  layout.chunksPerCounter = (chunks + layout.counterCount - 1) / layout.counterCount;
  const uint32_t needed = layout.capacityChunks();
  const uint32_t maxWidth = std::max(std::bit_floor(maxImageSize / kStoredChunkSize), 1u);
  const auto side = static_cast<uint32_t>(std::ceil(std::sqrt(static_cast<double>(needed))));
  layout.widthChunks = std::min(std::bit_ceil(side), maxWidth);
  layout.heightChunks = (needed + layout.widthChunks - 1) / layout.widthChunks;
  return layout;
}

}  // namespace sg::shadel
