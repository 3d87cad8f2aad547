// The glTF PBR result darkened by the frame's ambient occlusion, sampled where
// this surface point lands on screen (the same place in both variants: a
// shadel of a visible surface and the pixel that shows it).
#include <framework/plugin/shaders/material.glsl>

vec4 aoDarken(Surface s) {
  vec4 lit = sgLayer(gltf_pbr);
  float ao = texture(aoImage, sgScreenUv(s.position)).r;
  return vec4(lit.rgb * ao, lit.a);
}
