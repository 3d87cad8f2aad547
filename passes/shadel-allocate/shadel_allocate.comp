#version 460
// Storage for the marked chunks of each owned remap entry: popcount of its
// occupancy, taken from one of kStorageCounters partitions picked by a hash
// of the entry (so allocation does not serialize on one counter). A full
// partition passes the request on to the next ones, so storage runs out only
// when no partition has room; then the overflow is counted and the entry left
// without storage: never a write out of bounds. Chunks that keep last frame's
// shading (reuse.glsl) get storage like the others but go on the reuse list,
// not on their object's list of chunks to shade.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/reuse.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;

// `count` chunks from the first partition, starting at `first`, that has room
// (compare-and-swap: a failed attempt takes nothing); SG_NO_STORAGE if none.
uint takeChunks(uint first, uint count) {
  for (uint i = 0u; i < params.storageCounters; ++i) {
    uint p = (first + i) % params.storageCounters;
    uint current = counters.allocated[p];
    while (current + count <= params.chunksPerCounter) {
      uint seen = atomicCompSwap(counters.allocated[p], current, current + count);
      if (seen == current) return p * params.chunksPerCounter + current;
      current = seen;
    }
  }
  return SG_NO_STORAGE;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.ownedEntryCount) return;
  SgOwnedEntry owned = ownedEntries[i];
  uvec2 halves = unpackUint2x32(remap[owned.entryIndex].occupancy);
  uint count = uint(bitCount(halves.x) + bitCount(halves.y));
  if (count == 0u) return;
  atomicAdd(counters.chunksMarked, count);
  atomicAdd(counters.levelChunks[min(owned.level, kMaxLevels - 1u)], count);
  uint base = takeChunks(sgStorageCounter(owned.entryIndex, params.storageCounters), count);
  if (base == SG_NO_STORAGE) {
    atomicAdd(counters.overflowChunks, count);
    return;  // storageBase stays SG_NO_STORAGE (shadel-clear)
  }
  remap[owned.entryIndex].storageBase = base;
  atomicAdd(counters.chunksAllocated, count);
  uvec2 reusedHalves = unpackUint2x32(sgReusedChunks(owned, remap[owned.entryIndex].occupancy));
  uint reused = uint(bitCount(reusedHalves.x) + bitCount(reusedHalves.y));
  if (reused > 0u) {
    atomicAdd(work[sgReuseCountSlot()], reused);
    atomicAdd(counters.chunksReused, reused);
  }
  if (count > reused) {
    atomicAdd(work[sgObjectChunksSlot(owned.instanceId)], count - reused);
    atomicAdd(counters.chunksShaded, count - reused);
  }
}
