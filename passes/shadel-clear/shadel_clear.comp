#version 460
// With SG_CLEAR_ENTRIES: resets the remap entries of the frame's live span
// only (entry_span.glsl: cost follows the live entries, not the allocated
// ones nor the virtual sheet). An owned entry's storageBase is its first
// chunk slot (chunk_slots.glsl): where its chunks' storage is kept from frame
// to frame. Without: the shade counters, the per-object work counts and the
// reuse list's.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;

#ifdef SG_CLEAR_ENTRIES
#include <framework/shadel/shaders/entry_span.glsl>

void main() {
  uint i = sgSpanEntry(64u);
  if (gl_LocalInvocationIndex == 0u && sgInSpan(i)) {  // what the per-entry passes visit (stats)
    atomicAdd(counters.entriesVisited, min(sgSpanEnd - i, 64u));
    atomicAdd(counters.entryGroupsVisited, 1u);
  }
  if (!sgInSpan(i)) return;
  SgOwnedEntry owned = ownedEntries[i];
  remap[owned.entryIndex].storageBase = i * SG_CHUNKS_PER_ENTRY;
  remap[owned.entryIndex].objectInstanceId = owned.instanceId;
  remap[owned.entryIndex].occupancy = uint64_t(0);
}
#else
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < params.objectCount) {
    work[sgObjectChunksSlot(i)] = 0u;
    work[sgObjectFillSlot(i)] = 0u;
  }
  if (i < kMaxLevels) counters.levelChunks[i] = 0u;
  if (i < kStaleAgeBins) counters.staleAgeChunks[i] = 0u;
  if (i < kMaxPersistentLayers) {
    counters.layerReused[i] = 0u;
    counters.layerComputed[i] = 0u;
  }
  if (i < kWorkGlobalSlots) work[sgReuseCountSlot() + i] = 0u;
  if (i == 0u) {
    counters.chunksShaded = 0u;
    counters.chunksReused = 0u;
    counters.chunksMarked = 0u;
    counters.chunksAllocated = 0u;
    counters.overflowChunks = 0u;
    counters.compositeMisses = 0u;
    counters.coveredPixels = 0u;
    counters.supportChunks = 0u;
    counters.staleMaxAge = 0u;
    counters.chunksRefreshed = 0u;
    counters.shadelsSkipped = 0u;
    counters.entriesVisited = 0u;
    counters.entryGroupsVisited = 0u;
  }
}
#endif
