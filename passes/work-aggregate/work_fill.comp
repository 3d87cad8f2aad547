#version 460
// Appends one work item per stored chunk of each owned entry to its object's
// list, or, for a chunk that keeps last frame's shading, to the reuse list.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/reuse.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.ownedEntryCount) return;
  SgOwnedEntry owned = ownedEntries[i];
  SgRemapEntry entry = remap[owned.entryIndex];
  if (entry.storageBase == SG_NO_STORAGE) return;
  uint64_t reused = sgReusedChunks(owned, entry.occupancy);
  uvec2 halves = unpackUint2x32(entry.occupancy & ~reused);
  uint count = uint(bitCount(halves.x) + bitCount(halves.y));
  uvec2 reusedHalves = unpackUint2x32(reused);
  uint reuseCount = uint(bitCount(reusedHalves.x) + bitCount(reusedHalves.y));
  uint first = count > 0u ? work[sgObjectOffsetSlot(owned.instanceId)] +
                                atomicAdd(work[sgObjectFillSlot(owned.instanceId)], count) : 0u;
  uint firstReused = reuseCount > 0u ? work[sgReuseOffsetSlot()] + atomicAdd(work[sgReuseFillSlot()], reuseCount) : 0u;
  uint n = 0u, shaded = 0u, copied = 0u;
  for (uint chunk = 0u; chunk < SG_CHUNKS_PER_ENTRY; ++chunk) {
    if (!sgIsChunkMarked(entry.occupancy, chunk)) continue;
    uint physical = entry.storageBase + n;  // == sgPhysicalChunk(entry, chunk)
    ++n;
    if (sgIsChunkMarked(reused, chunk)) {
      uint slot = sgWorkItemSlot(firstReused + copied++);
      work[slot] = sgPhysicalChunk(previousRemap[owned.entryIndex], chunk);
      work[slot + 1u] = physical;
      continue;
    }
    uint slot = sgWorkItemSlot(first + shaded++);
    work[slot] = owned.entryIndex;
    work[slot + 1u] = chunk;
    work[slot + 2u] = owned.level;
    work[slot + 3u] = physical;
  }
}
