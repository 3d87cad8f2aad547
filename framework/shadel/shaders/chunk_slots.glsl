// Stable allocation (issue 15): where each marked chunk is stored, kept while
// it stays marked. One buffer: for owned entry i (ownedEntries[i]) its 64
// chunk slots at i * 64 (the remap entry's storageBase, set by shadel-clear);
// then per owned entry two 64-bit masks, the chunks with a slot and those
// that got it this frame (fresh: their storage holds nothing of them yet);
// then the free list: a count and a stack of free physical chunks.
// shadel-allocate frees the slots of chunks no longer marked, then gives the
// newly marked ones slots from the stack. The masks let every pass skip an
// entry's 64 slots when nothing there is stored or changed.
#ifndef SG_CHUNK_SLOTS_GLSL
#define SG_CHUNK_SLOTS_GLSL

layout(set = 0, binding = kBindChunkSlots, std430) buffer ChunkSlots { uint chunkSlots[]; };

uint sgSlotMaskSlot(uint ownedIndex) { return params.ownedEntryCount * SG_CHUNKS_PER_ENTRY + 4u * ownedIndex; }
uint sgFreeCountSlot() { return params.ownedEntryCount * (SG_CHUNKS_PER_ENTRY + 4u); }
uint sgFreeStackSlot(uint i) { return sgFreeCountSlot() + 1u + i; }

// The chunks of owned entry `ownedIndex` that have storage.
uint64_t sgStoredMask(uint ownedIndex) {
  uint at = sgSlotMaskSlot(ownedIndex);
  return packUint2x32(uvec2(chunkSlots[at], chunkSlots[at + 1u]));
}
// Those of them that got it this frame.
uint64_t sgFreshMask(uint ownedIndex) {
  uint at = sgSlotMaskSlot(ownedIndex) + 2u;
  return packUint2x32(uvec2(chunkSlots[at], chunkSlots[at + 1u]));
}
void sgSetSlotMasks(uint ownedIndex, uint64_t stored, uint64_t fresh) {
  uint at = sgSlotMaskSlot(ownedIndex);
  uvec2 s = unpackUint2x32(stored), f = unpackUint2x32(fresh);
  chunkSlots[at] = s.x;
  chunkSlots[at + 1u] = s.y;
  chunkSlots[at + 2u] = f.x;
  chunkSlots[at + 3u] = f.y;
}

// The lowest set bit of a non-zero mask.
uint sgLowestChunk(uint64_t bits) {
  uvec2 halves = unpackUint2x32(bits);
  return halves.x != 0u ? uint(findLSB(halves.x)) : 32u + uint(findLSB(halves.y));
}

// Whether the chunk can have a slot: it is marked and its entry has storage
// (its slot is then chunkSlots[entry.storageBase + chunkIndex]).
bool sgChunkHasSlot(SgRemapEntry entry, uint chunkIndex) {
  return sgIsChunkMarked(entry.occupancy, chunkIndex) && entry.storageBase != SG_NO_STORAGE;
}
uint sgSlotChunk(uint slot) { return slot == kNoSlot ? SG_INVALID_CHUNK : slot; }

// The physical chunk of a marked chunk, SG_INVALID_CHUNK when it is not marked or has no storage.
uint sgStoredChunk(SgRemapEntry entry, uint chunkIndex) {
  if (!sgChunkHasSlot(entry, chunkIndex)) return SG_INVALID_CHUNK;
  return sgSlotChunk(chunkSlots[entry.storageBase + chunkIndex]);
}

// The marked chunks of owned entry `ownedIndex` stored last frame too, at the same place.
uint64_t sgKeptChunks(uint ownedIndex, uint64_t occupancy) {
  return occupancy & sgStoredMask(ownedIndex) & ~sgFreshMask(ownedIndex);
}

// Was this marked chunk stored last frame too (its storage may hold its shading)?
bool sgChunkKept(SgRemapEntry entry, uint chunkIndex) {
  if (entry.storageBase == SG_NO_STORAGE) return false;
  return sgIsChunkMarked(sgKeptChunks(entry.storageBase / SG_CHUNKS_PER_ENTRY, entry.occupancy), chunkIndex);
}

#endif
