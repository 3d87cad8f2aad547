#version 460
// Copies each chunk on the reuse list (work-aggregate) from last frame's shade
// storage to its place in this frame's: shading kept across frames, one 8x8
// workgroup per chunk. Dispatched in rows like the shade lists.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindLayerImage, rgba16f) uniform writeonly image2D shaded;
layout(set = 0, binding = kBindLayerHistory) uniform sampler2D previousShaded;

void main() {
  uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (group >= work[sgReuseCountSlot()]) return;  // the surplus of the last row
  uint item = sgWorkItemSlot(work[sgReuseOffsetSlot()] + group);
  uint texel = gl_LocalInvocationID.y * SG_CHUNK_SIZE + gl_LocalInvocationID.x;
  ivec2 from = ivec2(sgStorageTexel(work[item], texel, params.storageWidthChunks));
  ivec2 to = ivec2(sgStorageTexel(work[item + 1u], texel, params.storageWidthChunks));
  imageStore(shaded, to, texelFetch(previousShaded, from, 0));
}
