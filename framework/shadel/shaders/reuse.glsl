// Which marked chunks keep their stored shading (shadel-allocate counts them,
// work-aggregate lists them apart): those of an object the host let reuse
// this frame (not a shade frame; same transform, material and storage layout
// as last frame) that were stored last frame too. With stable allocation such
// a chunk is still where it was (chunk_slots.glsl), so its shading needs no
// copy. In budget mode (params.staleAgeLimit > 0) a candidate whose shading
// is older than that many raster frames is shaded instead, and a fraction of
// those exactly that old, picked by a hash of their place (the shade stamps
// say when each was shaded).
#ifndef SG_REUSE_GLSL
#define SG_REUSE_GLSL

#include "decoupled.glsl"

layout(set = 0, binding = kBindShadeStamps, std430) buffer ShadeStamps { uint stamps[]; };

// Chunks that could keep their stored shading, whatever its age. `ownedIndex`: the entry's place in ownedEntries.
uint64_t sgReuseCandidates(uint ownedIndex, SgOwnedEntry owned, uint64_t occupancy) {
#ifdef SG_SHADE_ALL
  return uint64_t(0);  // the shade frame's own list (frames in flight): every chunk is shaded
#else
  if (objects[owned.instanceId].reuse == 0u) return uint64_t(0);
  return sgKeptChunks(ownedIndex, occupancy);
#endif
}

// Raster frames since the shading of a kept chunk (`base`: its entry's first slot) was computed.
uint sgChunkAge(uint base, uint chunk) {
  return params.frameNumber - stamps[chunkSlots[base + chunk]];
}

bool sgRefreshForAge(uint age, uint entryIndex, uint chunk) {
  if (age != params.staleAgeLimit) return age > params.staleAgeLimit;
  uint h = (entryIndex * SG_CHUNKS_PER_ENTRY + chunk) * 2654435761u;  // Knuth's multiplicative hash
  return (h >> 16) < params.staleAgeFraction;
}

// Those of the candidates (sgReuseCandidates) that keep their shading.
uint64_t sgReusedOf(uint ownedIndex, SgOwnedEntry owned, uint64_t candidates) {
  if (params.staleAgeLimit == 0u || params.stampsBound == 0u) return candidates;
  uint64_t kept = candidates;
  // Over the candidates' bits only: a loop over all 64 chunks costs every lane 64 turns on lavapipe.
  for (uint64_t left = candidates; left != uint64_t(0); left &= left - uint64_t(1)) {
    uint chunk = sgLowestChunk(left);
    if (sgRefreshForAge(sgChunkAge(ownedIndex * SG_CHUNKS_PER_ENTRY, chunk), owned.entryIndex, chunk))
      kept &= ~(uint64_t(1) << chunk);
  }
  return kept;
}

uint64_t sgReusedChunks(uint ownedIndex, SgOwnedEntry owned, uint64_t occupancy) {
  return sgReusedOf(ownedIndex, owned, sgReuseCandidates(ownedIndex, owned, occupancy));
}

#endif
