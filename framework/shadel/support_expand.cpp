#include <shadelgraph/shadel/support_expand.hpp>

#include <algorithm>
#include <bit>
#include <vector>

namespace sg::shadel {
namespace {

bool isMarkedAt(std::span<const RemapEntry> remap, uint32_t entriesPerSideLog2, glm::ivec2 chunk) {
  const glm::uvec2 c(chunk);
  const uint32_t entry = ((c.y >> 3) << entriesPerSideLog2) | (c.x >> 3);
  return (remap[entry].occupancy >> ((c.y & 7u) * kEntryChunks + (c.x & 7u))) & 1u;
}

}  // namespace

ChunkSpan chunkSpanOf(const LevelRect& rect) {
  return {rect.origin >> kChunkSizeLog2, (rect.origin + rect.size + (kChunkSize - 1)) >> kChunkSizeLog2};
}

uint64_t supportMaskOf(std::span<const RemapEntry> remap, uint32_t entriesPerSideLog2, const LevelRect& rect,
                       uint32_t entryIndex, uint32_t radius) {
  const int r = int(std::min(radius, kMaxSupportChunks));
  if (r == 0) return 0;
  const ChunkSpan span = chunkSpanOf(rect);
  const glm::ivec2 entry(int(entryIndex & ((1u << entriesPerSideLog2) - 1u)), int(entryIndex >> entriesPerSideLog2));
  uint64_t mask = 0;
  for (uint32_t bit = 0; bit < kChunksPerEntry; ++bit) {
    const glm::ivec2 chunk = entry * int(kEntryChunks) + glm::ivec2(int(bit % kEntryChunks), int(bit / kEntryChunks));
    if (!span.contains(chunk)) continue;
    bool nearMarked = false;
    for (int dy = -r; dy <= r && !nearMarked; ++dy)
      for (int dx = -r; dx <= r && !nearMarked; ++dx) {
        const glm::ivec2 neighbour = chunk + glm::ivec2(dx, dy);
        if ((dx || dy) && span.contains(neighbour)) nearMarked = isMarkedAt(remap, entriesPerSideLog2, neighbour);
      }
    if (nearMarked) mask |= uint64_t(1) << bit;
  }
  return mask;
}

uint32_t expandSupport(std::span<RemapEntry> remap, const SupportTables& tables) {
  // Gather from the original occupancy (the shader's first dispatch) ...
  std::vector<uint64_t> masks(tables.ownedEntries.size(), 0);
  for (size_t i = 0; i < masks.size(); ++i) {
    const OwnedEntry& owned = tables.ownedEntries[i];
    if (owned.instanceId >= tables.supportChunks.size() || tables.supportChunks[owned.instanceId] == 0) continue;
    const GpuShadelInstance& instance = tables.instances[owned.instanceId];
    if (owned.level >= instance.levelCount) continue;
    masks[i] = supportMaskOf(remap, tables.entriesPerSideLog2, tables.levelRects[instance.firstLevelRect + owned.level],
                             owned.entryIndex, tables.supportChunks[owned.instanceId]);
  }
  // ... then apply (its second dispatch).
  uint32_t added = 0;
  for (size_t i = 0; i < masks.size(); ++i) {
    RemapEntry& entry = remap[tables.ownedEntries[i].entryIndex];
    const uint64_t newBits = masks[i] & ~entry.occupancy;
    entry.occupancy |= newBits;
    added += uint32_t(std::popcount(newBits));
  }
  return added;
}

}  // namespace sg::shadel
