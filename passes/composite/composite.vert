#version 460
// Decoupled objects once more: same shading UV and `precise` depth as shadel-mark.
// Also the object's level table (flat): the fragment shader would otherwise
// read it per pixel, and on lavapipe a buffer read in a fragment shader is a
// loop over the 8 lanes.
#define SG_VERTEX_SHADER
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/object.glsl>
#include <framework/shadel/shaders/decoupled.glsl>

layout(location = 0) out vec2 outShadingUv;
#ifdef SG_ALPHA_TEST  // alpha-mask objects: what alpha_test.glsl reads
layout(location = 1) out vec2 outUv0;
layout(location = 2) out vec2 outUv1;
layout(location = 3) out float outColorAlpha;
#endif
layout(location = 4) flat out uvec3 outLevels;  // level0Size, levelCount, firstLevelRect

void main() {
  SgDecoupledObject o = objects[object.objectId];
  outShadingUv = (o.shadingUvSet == 1u ? inUv1 : inUv0) - o.tileOffset;
  precise vec4 world = object.model * vec4(inPosition, 1.0);
  precise vec4 clip = frame.viewProjection * world;
  gl_Position = clip;
  SgShadelInstance instance = shadelInstances[object.objectId];
  outLevels = uvec3(instance.level0Size, instance.levelCount, instance.firstLevelRect);
#ifdef SG_ALPHA_TEST
  outUv0 = inUv0;
  outUv1 = inUv1;
  outColorAlpha = inColor.a;
#endif
}
