#version 460
// Appends one work item per stored chunk of each owned entry to its object's
// list, or, for a chunk that keeps last frame's shading, to the reuse list.
// With shading kept between frames it also stamps every stored chunk with the
// frame its shading was computed in (this frame, or the reused chunk's own),
// and counts the oldest reused shading, the chunks shaded for their age and
// (budget mode) the reusable chunks by age.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/reuse.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;
layout(set = 0, binding = kBindShadeStamps, std430) buffer ShadeStamps { uint stamps[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.ownedEntryCount) return;
  SgOwnedEntry owned = ownedEntries[i];
  SgRemapEntry entry = remap[owned.entryIndex];
  if (entry.storageBase == SG_NO_STORAGE) return;
  uint64_t candidates = sgReuseCandidates(owned, entry.occupancy);
  uint64_t reused = sgReusedChunks(owned, entry.occupancy);
  uvec2 halves = unpackUint2x32(entry.occupancy & ~reused);
  uint count = uint(bitCount(halves.x) + bitCount(halves.y));
  uvec2 reusedHalves = unpackUint2x32(reused);
  uint reuseCount = uint(bitCount(reusedHalves.x) + bitCount(reusedHalves.y));
  uint first = count > 0u ? work[sgObjectOffsetSlot(owned.instanceId)] +
                                atomicAdd(work[sgObjectFillSlot(owned.instanceId)], count) : 0u;
  uint firstReused = reuseCount > 0u ? work[sgReuseOffsetSlot()] + atomicAdd(work[sgReuseFillSlot()], reuseCount) : 0u;
  bool stamped = params.stampsBound != 0u;
  bool budget = stamped && params.staleAgeLimit != 0u;
  uint n = 0u, shaded = 0u, copied = 0u, oldest = 0u, refreshed = 0u;
  for (uint chunk = 0u; chunk < SG_CHUNKS_PER_ENTRY; ++chunk) {
    if (!sgIsChunkMarked(entry.occupancy, chunk)) continue;
    uint physical = entry.storageBase + n;  // == sgPhysicalChunk(entry, chunk)
    ++n;
    if (budget && sgIsChunkMarked(candidates, chunk)) {
      uint age = sgChunkAge(owned.entryIndex, chunk);
      atomicAdd(counters.staleAgeChunks[min(age, kStaleAgeBins - 1u)], 1u);
      if (!sgIsChunkMarked(reused, chunk)) ++refreshed;
    }
    if (sgIsChunkMarked(reused, chunk)) {
      uint slot = sgWorkItemSlot(firstReused + copied++);
      uint from = sgPhysicalChunk(previousRemap[owned.entryIndex], chunk);
      work[slot] = from;
      work[slot + 1u] = physical;
      if (stamped) {
        stamps[physical] = previousStamps[from];
        oldest = max(oldest, params.frameNumber - previousStamps[from]);
      }
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
