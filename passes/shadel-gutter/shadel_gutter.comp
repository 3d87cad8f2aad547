#version 460
// Fills the gutter of every stored chunk's tile in the composited layer: its
// column 8 and row 8 get the first column and row of the chunks right of,
// below and diagonally after it (shadel_address.glsl, sgStoredTexel), so
// composite reads a level's whole bilinear footprint from one tile. Past the
// level's edge, or where that neighbour chunk has no storage this frame (no
// pixel's footprint started in it: the edge of what is visible at this level),
// the gutter repeats the chunk's own edge shadel, as if clamped there.
// 32 owned remap entries of the live span per workgroup (a workgroup per entry cost more in
// dispatch than the copies); its 64 lanes share their stored chunks' 17
// gutter texels each.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/entry_span.glsl>

layout(local_size_x = 64) in;
layout(set = 0, binding = kBindLayerImage, rgba16f) uniform image2D shaded;

const uint kGutterTexels = 2u * SG_CHUNK_SIZE + 1u;  // column 8, row 8, the corner
const uint kEntriesPerGroup = 32u;                     // 8 KiB of listed chunks: within every device's 16 KiB
shared uint chunkCount;
shared uint chunks[kEntriesPerGroup * SG_CHUNKS_PER_ENTRY];  // entry of this group << 16 | chunk

// The physical chunk of the chunk holding `shadel`, SG_INVALID_CHUNK past the level's edge or without storage.
uint storedChunk(uvec2 shadel, SgLevelRect rect) {
  if (any(greaterThanEqual(shadel - rect.origin, uvec2(rect.size)))) return SG_INVALID_CHUNK;
  SgShadelAddress a = sgShadelAddress(shadel, params.entriesPerSideLog2);
  return sgStoredChunk(remap[a.entryIndex], a.chunkIndex);
}

void main() {
  uint lane = gl_LocalInvocationIndex;
  uint first = sgSpanGroupFirst(kEntriesPerGroup);
  if (lane == 0u) chunkCount = 0u;
  barrier();
  // Each lane lists its entry's stored chunks.
  if (lane < kEntriesPerGroup && sgInSpan(first + lane)) {
    SgRemapEntry entry = remap[ownedEntries[first + lane].entryIndex];
    uint64_t stored = entry.occupancy & sgStoredMask(first + lane);
    uvec2 halves = unpackUint2x32(stored);
    uint count = uint(bitCount(halves.x) + bitCount(halves.y));
    if (count != 0u) {
      uint at = atomicAdd(chunkCount, count), place = 0u;
      for (uint c = 0u; c < SG_CHUNKS_PER_ENTRY; ++c)
        if (sgIsChunkMarked(stored, c)) chunks[at + place++] = (lane << 16u) | c;
    }
  }
  barrier();
  for (uint t = lane; t < chunkCount * kGutterTexels; t += gl_WorkGroupSize.x) {
    uint item = chunks[t / kGutterTexels], k = t % kGutterTexels;
    uint ownedIndex = first + (item >> 16u);
    SgOwnedEntry owned = ownedEntries[ownedIndex];
    uint physical = chunkSlots[ownedIndex * SG_CHUNKS_PER_ENTRY + (item & 0xFFu)];
    SgLevelRect rect = sgLevelRect(owned.instanceId, owned.level);
    uvec2 origin = sgVirtualShadel(SgShadelAddress(owned.entryIndex, item & 0xFFu, 0u), params.entriesPerSideLog2);
    uvec2 inTile = k < SG_CHUNK_SIZE ? uvec2(SG_CHUNK_SIZE, k)
                   : k < 2u * SG_CHUNK_SIZE ? uvec2(k - SG_CHUNK_SIZE, SG_CHUNK_SIZE) : uvec2(SG_CHUNK_SIZE);
    uvec2 shadel = origin + inTile;
    uint source = storedChunk(shadel, rect);
    uvec2 from = source == SG_INVALID_CHUNK
                     ? sgStoredTexel(physical, min(inTile, uvec2(SG_CHUNK_SIZE - 1u)), params.storageWidthChunks)
                     : sgStoredTexel(source, shadel & (SG_CHUNK_SIZE - 1u), params.storageWidthChunks);
    imageStore(shaded, ivec2(sgStoredTexel(physical, inTile, params.storageWidthChunks)), imageLoad(shaded, ivec2(from)));
  }
}
