#version 460
// Stable allocation (chunk_slots.glsl): a chunk keeps its storage for as long
// as it stays marked. Two steps, a barrier apart (SG_PHASE; the host resets
// the slots and free list when the tables or the storage size change):
// 1 per owned entry, the slots of chunks no longer marked go back on the
//   free list; those still marked are kept (no longer fresh);
// 2 per owned entry, its newly marked chunks take slots from the free list
//   (one compare-and-swap on its count for the whole entry), marked fresh.
//   The entry's masks (chunk_slots.glsl) let both skip untouched entries.
//   With too few free, the entry's new chunks stay without storage and the
//   overflow is counted: never a write out of bounds (the adjuster raises
//   the bias). Pushes and pops never meet in one step, so the stack needs no
//   more than its count. Step 2 also counts the chunks that keep their
//   shading (reuse.glsl) apart from those to shade.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/entry_span.glsl>
#include <framework/shadel/shaders/reuse.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 64) in;

#ifndef SG_PHASE
#define SG_PHASE 2
#endif

uint bitsSet(uint64_t bits) {
  uvec2 halves = unpackUint2x32(bits);
  return uint(bitCount(halves.x) + bitCount(halves.y));
}

void main() {
  uint i = sgSpanEntry(64u);
  if (!sgInSpan(i)) return;
  uint base = i * SG_CHUNKS_PER_ENTRY;
#if SG_PHASE == 1
  // The slot masks first: most live entries have none, and leave before the remap look-up.
  uint64_t stored = sgStoredMask(i);
  if (stored == uint64_t(0) && sgFreshMask(i) == uint64_t(0)) return;
  uint64_t occupancy = remap[ownedEntries[i].entryIndex].occupancy;
  uint64_t freed = stored & ~occupancy;
  sgSetSlotMasks(i, stored & occupancy, uint64_t(0));  // what stays is kept, no longer fresh
  uint count = bitsSet(freed);
  if (count == 0u) return;
  uint top = atomicAdd(chunkSlots[sgFreeCountSlot()], count);
  for (uint k = 0u; k < count; ++k) {
    uint c = sgLowestChunk(freed);
    freed &= freed - uint64_t(1);
    chunkSlots[sgFreeStackSlot(top + k)] = chunkSlots[base + c];
    chunkSlots[base + c] = kNoSlot;
  }
#else
  SgOwnedEntry owned = ownedEntries[i];
  uint64_t occupancy = remap[owned.entryIndex].occupancy;
  uint marked = bitsSet(occupancy);
  if (marked == 0u) return;
  uint64_t stored = sgStoredMask(i);
  atomicAdd(counters.chunksMarked, marked);
  atomicAdd(counters.levelChunks[min(owned.level, kMaxLevels - 1u)], marked);
  uint64_t missing = occupancy & ~stored;
  uint need = bitsSet(missing);
  if (need > 0u) {
    uint free = chunkSlots[sgFreeCountSlot()];
    bool taken = false;
    while (free >= need) {
      uint seen = atomicCompSwap(chunkSlots[sgFreeCountSlot()], free, free - need);
      if (seen == free) {
        taken = true;
        break;
      }
      free = seen;
    }
    if (taken) {
      for (uint k = free; missing != uint64_t(0); missing &= missing - uint64_t(1))  // pops stack[free - need, free)
        chunkSlots[base + sgLowestChunk(missing)] = chunkSlots[sgFreeStackSlot(--k)];
      sgSetSlotMasks(i, occupancy, occupancy & ~stored);
      stored = occupancy;
    } else {
      atomicAdd(counters.overflowChunks, need);  // its new chunks stay without storage
    }
  }
  uint storedCount = bitsSet(stored);
  if (storedCount == 0u) return;
  atomicAdd(counters.chunksAllocated, storedCount);
  uint reused = bitsSet(sgReusedChunks(i, owned, occupancy));
  if (reused > 0u) {
    atomicAdd(work[sgReuseCountSlot()], reused);
    atomicAdd(counters.chunksReused, reused);
  }
  if (storedCount > reused) {
    atomicAdd(work[sgObjectChunksSlot(owned.instanceId)], storedCount - reused);
    atomicAdd(counters.chunksShaded, storedCount - reused);
  }
#endif
}
