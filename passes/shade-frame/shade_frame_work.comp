#version 460
// The shade frame's own work list (frames in flight, issue 15): it reshades
// every stored chunk of its frame, after that frame's composite. SG_PHASE 0
// zeroes the list's counters, SG_PHASE 1 counts each owned entry's stored
// chunks for its object; work-offsets and work-fill (built with SG_SHADE_ALL:
// nothing reused) then lay the list out as for a raster frame.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>
#if SG_PHASE != 0
#include <framework/shadel/shaders/entry_span.glsl>
#endif

layout(local_size_x = 64) in;

void main() {
  uint i = gl_GlobalInvocationID.x;
#if SG_PHASE == 0
  if (i < kWorkSlotsPerObject * params.objectCount + kWorkGlobalSlots) work[i] = 0u;
#else
  i = sgSpanEntry(64u);
  if (!sgInSpan(i)) return;
  SgOwnedEntry owned = ownedEntries[i];
  SgRemapEntry entry = remap[owned.entryIndex];
  uvec2 halves = unpackUint2x32(entry.occupancy & sgStoredMask(i));
  uint stored = uint(bitCount(halves.x) + bitCount(halves.y));
  if (stored > 0u) atomicAdd(work[sgObjectChunksSlot(owned.instanceId)], stored);
#endif
}
