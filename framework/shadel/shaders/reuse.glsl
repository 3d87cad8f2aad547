// Which marked chunks keep last frame's shading (shadel-allocate counts them,
// work-aggregate lists them for shade-reuse's copy): those of an object the
// host let reuse this frame (not a shade frame; same transform, material and
// storage layout as last frame) that last frame's remap table also holds, in
// the same entry, owned by the same object, with storage. In budget mode
// (params.staleAgeLimit > 0) a candidate whose shading is older than that
// many raster frames is shaded instead, and a fraction of those exactly that
// old, picked by a hash of their place (the shade stamps say when each was shaded).
#ifndef SG_REUSE_GLSL
#define SG_REUSE_GLSL

#include "decoupled.glsl"

layout(set = 0, binding = kBindPreviousRemap, std430) readonly buffer PreviousRemap { SgRemapEntry previousRemap[]; };
layout(set = 0, binding = kBindPreviousStamps, std430) readonly buffer PreviousStamps { uint previousStamps[]; };

// Chunks that could keep last frame's shading, whatever their age.
uint64_t sgReuseCandidates(SgOwnedEntry owned, uint64_t occupancy) {
#ifdef SG_SHADE_ALL
  return uint64_t(0);  // the shade frame's own list (frames in flight): every chunk is shaded
#else
  if (objects[owned.instanceId].reuse == 0u) return uint64_t(0);
  SgRemapEntry previous = previousRemap[owned.entryIndex];
  if (previous.storageBase == SG_NO_STORAGE || previous.objectInstanceId != owned.instanceId) return uint64_t(0);
  return occupancy & previous.occupancy;
#endif
}

// Raster frames since the shading of `chunk` (stored last frame in entry `entryIndex`) was computed.
uint sgChunkAge(uint entryIndex, uint chunk) {
  return params.frameNumber - previousStamps[sgPhysicalChunk(previousRemap[entryIndex], chunk)];
}

bool sgRefreshForAge(uint age, uint entryIndex, uint chunk) {
  if (age != params.staleAgeLimit) return age > params.staleAgeLimit;
  uint h = (entryIndex * SG_CHUNKS_PER_ENTRY + chunk) * 2654435761u;  // Knuth's multiplicative hash
  return (h >> 16) < params.staleAgeFraction;
}

uint64_t sgReusedChunks(SgOwnedEntry owned, uint64_t occupancy) {
  uint64_t candidates = sgReuseCandidates(owned, occupancy);
  if (params.staleAgeLimit == 0u || params.stampsBound == 0u || candidates == uint64_t(0)) return candidates;
  uint64_t kept = candidates;
  for (uint chunk = 0u; chunk < SG_CHUNKS_PER_ENTRY; ++chunk)
    if (sgIsChunkMarked(candidates, chunk) && sgRefreshForAge(sgChunkAge(owned.entryIndex, chunk), owned.entryIndex, chunk))
      kept &= ~(uint64_t(1) << chunk);
  return kept;
}

#endif
