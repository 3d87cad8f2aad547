// Which marked chunks keep last frame's shading (shadel-allocate counts them,
// work-aggregate lists them for shade-reuse's copy): those of an object the
// host let reuse this frame (not a shade frame; same transform, material and
// storage layout as last frame) that last frame's remap table also holds, in
// the same entry, owned by the same object, with storage.
#ifndef SG_REUSE_GLSL
#define SG_REUSE_GLSL

#include "decoupled.glsl"

layout(set = 0, binding = kBindPreviousRemap, std430) readonly buffer PreviousRemap { SgRemapEntry previousRemap[]; };

uint64_t sgReusedChunks(SgOwnedEntry owned, uint64_t occupancy) {
#ifdef SG_SHADE_ALL
  return uint64_t(0);  // the shade frame's own list (frames in flight): every chunk is shaded
#else
  if (objects[owned.instanceId].reuse == 0u) return uint64_t(0);
  SgRemapEntry previous = previousRemap[owned.entryIndex];
  if (previous.storageBase == SG_NO_STORAGE || previous.objectInstanceId != owned.instanceId) return uint64_t(0);
  return occupancy & previous.occupancy;
#endif
}

#endif
