#include <shadelgraph/shadel/shadel_address.hpp>

namespace sg::shadel {

uint32_t physicalChunkOf(std::span<const RemapEntry> remap, glm::uvec2 shadel, uint32_t entriesPerSideLog2) {
  const ShadelAddress address = addressOf(shadel, entriesPerSideLog2);
  if (address.entryIndex >= remap.size()) return kInvalidChunk;
  return physicalChunk(remap[address.entryIndex], address.chunkIndex);
}

}  // namespace sg::shadel
