#version 460
// Copies each chunk on the reuse list (work-aggregate) from last frame's image
// of a view-independent layer kept across frames (an image pair) to this
// frame's, at the same place (stable allocation). The shade storage itself is
// one image and needs no copy. One 8x8 workgroup per chunk, dispatched in rows
// like the shade lists. SG_REUSE_FORMAT: the image's format.
#include <framework/shadel/shaders/decoupled.glsl>
#include <framework/shadel/shaders/work.glsl>

#ifndef SG_REUSE_FORMAT
#define SG_REUSE_FORMAT rgba16f
#endif

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindLayerImage, SG_REUSE_FORMAT) uniform writeonly image2D shaded;
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
