#pragma once
// support-expand on the CPU: the reference twin of
// passes/support-expand/support_expand.comp. A layer that reads neighbours
// (radius <= 8 shadels = one chunk) needs the chunks around the visible ones
// shaded too, so every chunk within `supportChunks` chunks (Chebyshev: the
// 8-neighbourhood for 1) of a chunk shadel-mark marked is marked as well, at
// the same level and only inside the same level rectangle (outside it the
// sheet belongs to another level or instance).
//
// No cascade: a chunk is added because a chunk marked *before the pass* is
// near it, never because of a chunk the pass itself added. So the masks of all
// owned entries are gathered from the original occupancy first and applied after.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include <shadelgraph/shadel/level_rect.hpp>
#include <shadelgraph/shadel/remap_entry.hpp>
#include <shadelgraph/shadel/shadel_gpu_tables.hpp>

namespace sg::shadel {

// Larger supportChunks values are clamped: the neighbours then stay within the
// next remap entry (and a radius of 8 shadels needs only 1).
inline constexpr uint32_t kMaxSupportChunks = 8;

// The chunks a level rectangle covers, in sheet chunk coordinates, [begin, end):
// every chunk overlapping [origin, origin + size), so a level smaller than a
// chunk, or not a multiple of 8, still has its partly covered chunks.
struct ChunkSpan {
  glm::uvec2 begin{0};
  glm::uvec2 end{0};
  bool contains(glm::ivec2 chunk) const {
    return chunk.x >= int(begin.x) && chunk.y >= int(begin.y) && chunk.x < int(end.x) && chunk.y < int(end.y);
  }
};
ChunkSpan chunkSpanOf(const LevelRect& rect);

// The support bits of one remap entry (bit = chunkY * 8 + chunkX): its chunks
// inside `rect` that have a chunk marked in `remap` (the dense table, index =
// entryIndex) within `radius` chunks, also inside `rect`. Reads only.
uint64_t supportMaskOf(std::span<const RemapEntry> remap, uint32_t entriesPerSideLog2, const LevelRect& rect,
                       uint32_t entryIndex, uint32_t radius);

// The GPU tables support-expand reads (framework/shadel/shaders/decoupled.glsl).
struct SupportTables {
  uint32_t entriesPerSideLog2 = 0;
  std::span<const GpuShadelInstance> instances;  // by instance id
  std::span<const LevelRect> levelRects;
  std::span<const OwnedEntry> ownedEntries;
  std::span<const uint32_t> supportChunks;  // by instance id (DecoupledObject::supportChunks); missing = 0
};

// The whole pass over the owned entries: gathers every owned entry's support
// mask from the occupancy as it is, then ORs them in. Entries of instances
// with supportChunks 0 are left alone. Returns the chunks added (the
// ShadeCounters::supportChunks the pass counts).
uint32_t expandSupport(std::span<RemapEntry> remap, const SupportTables& tables);

}  // namespace sg::shadel
