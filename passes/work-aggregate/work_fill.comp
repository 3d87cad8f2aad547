#version 460
// Appends one work item per stored chunk of each owned entry to its object's list.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.ownedEntryCount) return;
  SgOwnedEntry owned = ownedEntries[i];
  SgRemapEntry entry = remap[owned.entryIndex];
  if (entry.storageBase == SG_NO_STORAGE) return;
  uvec2 halves = unpackUint2x32(entry.occupancy);
  uint count = uint(bitCount(halves.x) + bitCount(halves.y));
  uint first = work[sgObjectOffsetSlot(owned.instanceId)] + atomicAdd(work[sgObjectFillSlot(owned.instanceId)], count);
  uint n = 0u;
  for (uint chunk = 0u; chunk < SG_CHUNKS_PER_ENTRY; ++chunk) {
    if (!sgIsChunkMarked(entry.occupancy, chunk)) continue;
    uint slot = sgWorkItemSlot(first + n);
    work[slot] = owned.entryIndex;
    work[slot + 1u] = chunk;
    work[slot + 2u] = owned.level;
    work[slot + 3u] = entry.storageBase + n;  // == sgPhysicalChunk(entry, chunk)
    ++n;
  }
}
