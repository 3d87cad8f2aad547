#version 460
// Fills the gutter of every stored chunk's tile in the composited layer: its
// column 8 and row 8 get the first column and row of the chunks right of,
// below and diagonally after it (shadel_address.glsl, sgStoredTexel), so
// composite reads a level's whole bilinear footprint from one tile. Past the
// level's edge, or where that neighbour chunk has no storage this frame (no
// pixel's footprint started in it: the edge of what is visible at this level),
// the gutter repeats the chunk's own edge shadel, as if clamped there.
// One workgroup per owned remap entry, one invocation per chunk.
#include <framework/shadel/shaders/decoupled.glsl>

layout(local_size_x = 64) in;
layout(set = 0, binding = kBindLayerImage, rgba16f) uniform image2D shaded;

// The physical chunk of the chunk holding `shadel`, SG_INVALID_CHUNK past the level's edge or without storage.
uint storedChunk(uvec2 shadel, SgLevelRect rect) {
  if (any(greaterThanEqual(shadel - rect.origin, uvec2(rect.size)))) return SG_INVALID_CHUNK;
  SgShadelAddress a = sgShadelAddress(shadel, params.entriesPerSideLog2);
  return sgPhysicalChunk(remap[a.entryIndex], a.chunkIndex);
}

void main() {
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (group >= params.ownedEntryCount) return;  // the surplus of the last row
  SgOwnedEntry owned = ownedEntries[group];
  uint chunk = gl_LocalInvocationIndex;
  uint physical = sgPhysicalChunk(remap[owned.entryIndex], chunk);
  if (physical == SG_INVALID_CHUNK) return;
  SgLevelRect rect = sgLevelRect(owned.instanceId, owned.level);
  uvec2 origin = sgVirtualShadel(SgShadelAddress(owned.entryIndex, chunk, 0u), params.entriesPerSideLog2);
  // Levels are powers of two: a neighbouring chunk is wholly inside the level or wholly past its edge.
  uint right = storedChunk(origin + uvec2(SG_CHUNK_SIZE, 0u), rect);
  uint below = storedChunk(origin + uvec2(0u, SG_CHUNK_SIZE), rect);
  uint corner = storedChunk(origin + uvec2(SG_CHUNK_SIZE), rect);
  for (uint k = 0u; k < 2u * SG_CHUNK_SIZE + 1u; ++k) {
    // Column 8 (k < 8), row 8 (k < 16), then the corner.
    uvec2 inTile = k < SG_CHUNK_SIZE ? uvec2(SG_CHUNK_SIZE, k)
                   : k < 2u * SG_CHUNK_SIZE ? uvec2(k - SG_CHUNK_SIZE, SG_CHUNK_SIZE) : uvec2(SG_CHUNK_SIZE);
    uint source = k < SG_CHUNK_SIZE ? right : k < 2u * SG_CHUNK_SIZE ? below : corner;
    uvec2 from = source == SG_INVALID_CHUNK
                     ? sgStoredTexel(physical, min(inTile, uvec2(SG_CHUNK_SIZE - 1u)), params.storageWidthChunks)
                     : sgStoredTexel(source, inTile & (SG_CHUNK_SIZE - 1u), params.storageWidthChunks);
    imageStore(shaded, ivec2(sgStoredTexel(physical, inTile, params.storageWidthChunks)), imageLoad(shaded, ivec2(from)));
  }
}
