#version 460
// Storage for the marked chunks of each owned remap entry: popcount of its
// occupancy, taken with atomicAdd from one of SG_STORAGE_COUNTERS partitions
// picked by a hash of the entry (so allocation does not serialize on one
// counter). A partition that is full counts the overflow and leaves the entry
// without storage: never a write out of bounds.
#include <plugins/decoupled/shaders/decoupled.glsl>
#include <plugins/decoupled/shaders/work.glsl>

layout(local_size_x = 64) in;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.ownedEntryCount) return;
  SgOwnedEntry owned = ownedEntries[i];
  uvec2 halves = unpackUint2x32(remap[owned.entryIndex].occupancy);
  uint count = uint(bitCount(halves.x) + bitCount(halves.y));
  if (count == 0u) return;
  atomicAdd(counters.chunksMarked, count);
  atomicAdd(counters.levelChunks[min(owned.level, SG_MAX_LEVELS - 1u)], count);
  uint storagePartition = sgStorageCounter(owned.entryIndex, params.storageCounters);
  uint base = atomicAdd(counters.allocated[storagePartition], count);
  if (base + count > params.chunksPerCounter) {
    atomicAdd(counters.overflowChunks, count);
    return;  // storageBase stays SG_NO_STORAGE (shadel-clear)
  }
  remap[owned.entryIndex].storageBase = storagePartition * params.chunksPerCounter + base;
  atomicAdd(counters.chunksAllocated, count);
  atomicAdd(work[sgObjectChunksSlot(owned.instanceId)], count);
}
