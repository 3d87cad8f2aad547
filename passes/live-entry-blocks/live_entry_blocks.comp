#version 460
// The blocks of owned entries the per-entry passes visit this frame: the
// frame's live spans (objects shaded now or last frame, decided on the CPU)
// cut in blocks of 64, without the blocks whose objects the occlusion cull
// hid both this frame and last frame. A hidden object's first hidden frame
// still visits its entries: nothing is marked, so shadel-allocate frees its
// chunks; after that its entries hold nothing and are left alone until it is
// seen again. One thread per candidate block appends the visited ones (any
// order: every per-entry pass's result is independent of workgroup order);
// threads below objectCount also record this frame's visibility.
#include <framework/shadel/shaders/decoupled.glsl>

layout(local_size_x = 64) in;

layout(set = 0, binding = kBindEntryBlocks, scalar) buffer EntryBlocks {
  SgEntryBlocksHeader header;
  SgEntryBlock blocks[];
};
layout(set = 0, binding = kBindObjectVisibility, scalar) buffer Visibility { uint visibility[]; };
layout(set = 0, binding = kBindCulledDraws, scalar) readonly buffer Draws { uint draws[]; };  // 5 per draw
layout(push_constant, scalar) uniform Push { SgEntryBlocksPush pc; };

bool visibleNow(uint object) { return pc.culled == 0u || draws[object * 5u + 1u] != 0u; }

bool visited(uint object) {
  return visibleNow(object) || pc.historyValid == 0u || visibility[(pc.parity ^ 1u) * pc.objectCount + object] != 0u;
}

#ifdef SG_BLOCKS_HEADER
// First, a dispatch of one: no block yet, indirect dispatches of none.
void main() {
  header.args64 = uint[3](0u, 1u, 1u);
  header.args32 = uint[3](0u, 1u, 1u);
  header.blockCount = 0u;
  header.pad = 0u;
}
#else
void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t < pc.objectCount) visibility[pc.parity * pc.objectCount + t] = visibleNow(t) ? 1u : 0u;
  if (t >= pc.candidateBlocks) return;
  uint s = 0u;
  while (s + 1u < pc.spanCount && pc.spans[s + 1u].blocks <= t) ++s;
  uint first = pc.spans[s].begin + (t - pc.spans[s].blocks) * kEntryBlockSize;
  uint last = min(first + kEntryBlockSize, pc.spans[s].end) - 1u;
  // Entries are grouped by object in ascending id: the block's objects are those from its first entry's to its last's.
  bool visit = false;
  for (uint o = ownedEntries[first].instanceId; o <= ownedEntries[last].instanceId && !visit; ++o) visit = visited(o);
  if (!visit) return;
  uint at = atomicAdd(header.blockCount, 1u);
  blocks[at] = SgEntryBlock(first, pc.spans[s].end);
  atomicAdd(header.args64[0], 1u);
  atomicAdd(header.args32[0], 2u);
}
#endif
