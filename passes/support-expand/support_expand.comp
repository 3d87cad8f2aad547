#version 460
// support-expand: marks the chunks around the ones shadel-mark marked, for
// objects whose layers read neighbours (objects[].supportChunks > 0: every
// chunk within that many chunks, the 8-neighbourhood for 1), at the same level
// and only inside the same level rectangle. The twin of
// framework/shadel/support_expand.cpp.
//
// Two dispatches of this file, so that nothing cascades: a chunk is added only
// because a chunk marked *by shadel-mark* is near it.
//   gather (the default): a workgroup per owned entry, a thread per chunk of it;
//     reads the original occupancy of the neighbouring chunks (possibly in
//     neighbouring entries) and writes the entry's mask to supportMasks. It
//     writes no occupancy, so every read sees shadel-mark's bits.
//   apply (SG_SUPPORT_APPLY defined): a thread per owned entry ORs its mask into the entry
//     (owned entries are distinct: no atomics) and counts the new bits.
// The workgroups of both form a 2D grid (x up to 65535) read back as one index.
#include <framework/shadel/shaders/decoupled.glsl>

// The transient buffer of the masks, one per owned entry.
layout(set = 0, binding = kBindSupportMasks, std430) buffer SupportMasks { uint64_t supportMasks[]; };

const uint SG_MAX_SUPPORT_CHUNKS = 8u;  // sg::shadel::kMaxSupportChunks

uint sgWorkgroupIndex() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

#ifndef SG_SUPPORT_APPLY
layout(local_size_x = 64) in;

shared uint maskHalves[2];  // the entry's 64-bit mask as two 32-bit words (atomicOr)

// Mirrors ChunkSpan::contains over sg::shadel::chunkSpanOf(rect) = [begin, end).
bool sgInSpan(ivec2 chunk, ivec2 begin, ivec2 end) {
  return all(greaterThanEqual(chunk, begin)) && all(lessThan(chunk, end));
}

bool sgMarkedAt(ivec2 chunk) {
  uvec2 c = uvec2(chunk);
  uint entry = ((c.y >> 3u) << params.entriesPerSideLog2) | (c.x >> 3u);
  return sgIsChunkMarked(remap[entry].occupancy, (c.y & 7u) * SG_ENTRY_CHUNKS + (c.x & 7u));
}

// Mirrors sg::shadel::supportMaskOf for one chunk: is a marked chunk within `radius`?
bool sgNearMarked(ivec2 chunk, int radius, ivec2 begin, ivec2 end) {
  if (!sgInSpan(chunk, begin, end)) return false;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      ivec2 neighbour = chunk + ivec2(dx, dy);
      if ((dx != 0 || dy != 0) && sgInSpan(neighbour, begin, end) && sgMarkedAt(neighbour)) return true;
    }
  return false;
}

void main() {
  uint ownedIndex = sgWorkgroupIndex();
  if (ownedIndex >= params.ownedEntryCount) return;  // the whole workgroup: barrier() stays uniform
  uint chunkIndex = gl_LocalInvocationIndex;
  if (chunkIndex == 0u) {
    maskHalves[0] = 0u;
    maskHalves[1] = 0u;
  }
  barrier();

  SgOwnedEntry owned = ownedEntries[ownedIndex];
  uint radius = owned.instanceId < params.objectCount ? min(objects[owned.instanceId].supportChunks, SG_MAX_SUPPORT_CHUNKS) : 0u;
  if (radius > 0u) {
    SgShadelInstance instance = shadelInstances[owned.instanceId];
    if (owned.level < instance.levelCount) {
      SgLevelRect rect = levelRects[sgLevelRectIndex(instance, owned.level)];
      // Chunks overlapping [origin, origin + size): partly covered ones count.
      ivec2 begin = ivec2(rect.origin >> SG_CHUNK_SIZE_LOG2);
      ivec2 end = ivec2((rect.origin + rect.size + (SG_CHUNK_SIZE - 1u)) >> SG_CHUNK_SIZE_LOG2);
      uint side = 1u << params.entriesPerSideLog2;
      ivec2 entry = ivec2(owned.entryIndex & (side - 1u), owned.entryIndex >> params.entriesPerSideLog2);
      ivec2 chunk = entry * int(SG_ENTRY_CHUNKS) + ivec2(chunkIndex & 7u, chunkIndex >> 3u);
      if (sgNearMarked(chunk, int(radius), begin, end)) atomicOr(maskHalves[chunkIndex >> 5u], 1u << (chunkIndex & 31u));
    }
  }
  barrier();
  // Written for every owned entry (0 without support): the buffer is transient, its contents undefined.
  if (chunkIndex == 0u) supportMasks[ownedIndex] = packUint2x32(uvec2(maskHalves[0], maskHalves[1]));
}
#else
layout(local_size_x = 64) in;

void main() {
  uint ownedIndex = sgWorkgroupIndex() * 64u + gl_LocalInvocationIndex;
  if (ownedIndex >= params.ownedEntryCount) return;
  uint entry = ownedEntries[ownedIndex].entryIndex;
  uint64_t occupancy = remap[entry].occupancy;
  uint64_t added = supportMasks[ownedIndex] & ~occupancy;
  if (added == uint64_t(0)) return;
  remap[entry].occupancy = occupancy | added;
  uvec2 halves = unpackUint2x32(added);
  atomicAdd(counters.supportChunks, uint(bitCount(halves.x) + bitCount(halves.y)));
}
#endif
