#version 460
// Appends one work item per stored chunk of each owned entry to its object's
// list, or, for a chunk that keeps its stored shading, to the reuse list
// (what shade-reuse copies in kept layers' image pairs). With shading kept
// between frames it also stamps every chunk it lists for shading with this
// frame, and counts the oldest kept shading, the chunks shaded for their age
// and (budget mode) the reusable chunks by age.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/entry_span.glsl>
#include <framework/shadel/shaders/reuse.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;

void main() {
  uint i = sgSpanEntry(64u);
  if (!sgInSpan(i)) return;
  SgOwnedEntry owned = ownedEntries[i];
  uint64_t occupancy = remap[owned.entryIndex].occupancy;
  uint64_t stored = occupancy & sgStoredMask(i);
  // Most live entries list nothing (an object's levels are mostly unseen): they leave before the reuse look-ups.
  if (stored == uint64_t(0)) return;
  uint64_t candidates = sgReuseCandidates(i, owned, occupancy);
  uint64_t reused = sgReusedOf(i, owned, candidates);
  uvec2 halves = unpackUint2x32(stored & ~reused);
  uint count = uint(bitCount(halves.x) + bitCount(halves.y));
  uvec2 reusedHalves = unpackUint2x32(reused);
  uint reuseCount = uint(bitCount(reusedHalves.x) + bitCount(reusedHalves.y));
  uint first = count > 0u ? work[sgObjectOffsetSlot(owned.instanceId)] +
                                atomicAdd(work[sgObjectFillSlot(owned.instanceId)], count) : 0u;
  uint firstReused = reuseCount > 0u ? work[sgReuseOffsetSlot()] + atomicAdd(work[sgReuseFillSlot()], reuseCount) : 0u;
  bool stamped = params.stampsBound != 0u;
  bool budget = stamped && params.staleAgeLimit != 0u;
  uint base = i * SG_CHUNKS_PER_ENTRY;
  uint shaded = 0u, copied = 0u, oldest = 0u, refreshed = 0u;
  // Over the stored chunks' bits, lowest first (the order a loop over all 64
  // chunks lists them in): lavapipe runs a loop as many turns as its busiest
  // lane, so 64 for every entry with anything stored.
  for (uint64_t left = stored; left != uint64_t(0); left &= left - uint64_t(1)) {
    uint chunk = sgLowestChunk(left);
    uint physical = chunkSlots[base + chunk];
    if (budget && sgIsChunkMarked(candidates, chunk)) {
      uint age = params.frameNumber - stamps[physical];
      atomicAdd(counters.staleAgeChunks[min(age, kStaleAgeBins - 1u)], 1u);
      if (!sgIsChunkMarked(reused, chunk)) ++refreshed;
    }
    if (sgIsChunkMarked(reused, chunk)) {
      // Its storage already holds its shading; kept layers' image pairs copy it across in place.
      uint slot = sgWorkItemSlot(firstReused + copied++);
      work[slot] = physical;
      work[slot + 1u] = physical;
      if (stamped) oldest = max(oldest, params.frameNumber - stamps[physical]);
      continue;
    }
    uint slot = sgWorkItemSlot(first + shaded++);
    work[slot] = owned.entryIndex;
    work[slot + 1u] = chunk;
    work[slot + 2u] = owned.level;
    work[slot + 3u] = physical;
    if (stamped) stamps[physical] = params.frameNumber;
  }
  if (oldest > 0u) atomicMax(counters.staleMaxAge, oldest);
  if (refreshed > 0u) atomicAdd(counters.chunksRefreshed, refreshed);
}
