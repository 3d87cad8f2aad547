// Stable allocation (issue 15): where each marked chunk is stored, kept while
// it stays marked. One buffer: for owned entry i (ownedEntries[i]) its 64
// chunk slots at i * 64 (the remap entry's storageBase, set by shadel-clear),
// then the free list: a count and a stack of free physical chunks.
// shadel-allocate frees the slots of chunks no longer marked, then gives the
// newly marked ones slots from the stack (flagged kSlotFresh for the frame).
#ifndef SG_CHUNK_SLOTS_GLSL
#define SG_CHUNK_SLOTS_GLSL

layout(set = 0, binding = kBindChunkSlots, std430) buffer ChunkSlots { uint chunkSlots[]; };

uint sgFreeCountSlot() { return params.ownedEntryCount * SG_CHUNKS_PER_ENTRY; }
uint sgFreeStackSlot(uint i) { return sgFreeCountSlot() + 1u + i; }

// The physical chunk of a marked chunk, SG_INVALID_CHUNK when it is not marked or has no storage.
uint sgStoredChunk(SgRemapEntry entry, uint chunkIndex) {
  if (!sgIsChunkMarked(entry.occupancy, chunkIndex) || entry.storageBase == SG_NO_STORAGE) return SG_INVALID_CHUNK;
  uint slot = chunkSlots[entry.storageBase + chunkIndex];
  return slot == kNoSlot ? SG_INVALID_CHUNK : slot & ~kSlotFresh;
}

// Was this marked chunk stored already last frame, at the same place (its storage may hold its shading)?
bool sgChunkKept(SgRemapEntry entry, uint chunkIndex) {
  if (!sgIsChunkMarked(entry.occupancy, chunkIndex) || entry.storageBase == SG_NO_STORAGE) return false;
  uint slot = chunkSlots[entry.storageBase + chunkIndex];
  return slot != kNoSlot && (slot & kSlotFresh) == 0u;
}

// The chunks of an owned entry (its first slot `base`) stored last frame too.
uint64_t sgKeptChunks(uint base, uint64_t occupancy) {
  uint64_t kept = uint64_t(0);
  for (uint c = 0u; c < SG_CHUNKS_PER_ENTRY; ++c) {
    uint slot = chunkSlots[base + c];
    if (sgIsChunkMarked(occupancy, c) && slot != kNoSlot && (slot & kSlotFresh) == 0u) kept |= uint64_t(1) << c;
  }
  return kept;
}

#endif
