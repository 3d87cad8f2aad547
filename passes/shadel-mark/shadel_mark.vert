#version 460
// Decoupled objects again, for their shading UVs; same `precise` position
// math as the z-prepass so the depth test finds exactly its depths.
// Also the object's detail levels, flat: the fragment shader would otherwise
// read them per pixel, and on lavapipe every storage-buffer read in a
// fragment shader is a loop over the 8 lanes (shadel_mark_levels.glsl).
#define SG_VERTEX_SHADER
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>
#include <passes/shadel-mark/shadel_mark_levels.glsl>

layout(location = 0) out vec2 outShadingUv;
#ifdef SG_ALPHA_TEST  // alpha-mask objects: what alpha_test.glsl reads
layout(location = 1) out vec2 outUv0;
layout(location = 2) out vec2 outUv1;
layout(location = 3) out float outColorAlpha;
#endif
#ifndef SG_MARK_BASELINE
layout(location = kMarkLevelsLocation) flat out uvec4 outLevels;
#endif

void main() {
  SgDecoupledObject o = objects[object.objectId];
  outShadingUv = (o.shadingUvSet == 1u ? inUv1 : inUv0) - o.tileOffset;
  precise vec4 world = object.model * vec4(inPosition, 1.0);
  precise vec4 clip = frame.viewProjection * world;
  gl_Position = clip;
#ifdef SG_ALPHA_TEST
  outUv0 = inUv0;
  outUv1 = inUv1;
  outColorAlpha = inColor.a;
#endif
#ifndef SG_MARK_BASELINE
  SgShadelInstance instance = shadelInstances[object.objectId];
  outLevels = uvec4(instance.level0Size, instance.levelCount, instance.firstOwnedEntry, instance.firstLevelRect);
#endif
}
