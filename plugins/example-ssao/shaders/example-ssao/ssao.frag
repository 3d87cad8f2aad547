#version 460
// Ambient occlusion from depth alone: the fraction of 16 samples on a disc
// around the pixel (radius `radius` in world units, projected) whose surface
// is in front of this one by less than the radius.
#include <framework/plugin/shaders/material.glsl>

layout(set = 0, binding = 1) uniform sampler2D depth;
layout(push_constant) uniform Constants { float radius; float strength; } pc;
layout(location = 0) in vec2 inUv;
layout(location = 0) out float outAo;

// View-space distance along -z of the depth at texel p.
float viewDepth(ivec2 p, mat4 inverseProjection) {
  const vec2 size = vec2(textureSize(depth, 0));
  const vec2 ndc = (vec2(p) + 0.5) / size * 2.0 - 1.0;
  const vec4 v = inverseProjection * vec4(ndc, texelFetch(depth, p, 0).r, 1.0);
  return -v.z / v.w;
}

void main() {
  const ivec2 p = ivec2(gl_FragCoord.xy);
  const ivec2 size = textureSize(depth, 0);
  if (texelFetch(depth, p, 0).r >= 1.0) {  // sky
    outAo = 1.0;
    return;
  }
  const mat4 inverseProjection = inverse(frame.projection);
  const float z = viewDepth(p, inverseProjection);
  const float pixels = pc.radius * frame.projection[1][1] * 0.5 * float(size.y) / z;
  float occluded = 0.0;
  for (int i = 0; i < 16; ++i) {
    const float angle = float(i) * 2.399963;  // golden angle
    const float r = sqrt((float(i) + 0.5) / 16.0) * pixels;
    const ivec2 q = clamp(p + ivec2(round(r * vec2(cos(angle), sin(angle)))), ivec2(0), size - 1);
    const float dz = z - viewDepth(q, inverseProjection);
    occluded += (dz > 0.02 * pc.radius && dz < pc.radius) ? 1.0 : 0.0;
  }
  outAo = 1.0 - pc.strength * occluded / 16.0;
}
