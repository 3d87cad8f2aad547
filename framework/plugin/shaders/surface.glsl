// The surface point a material shades, with the derivatives of its UVs per
// sample step: per pixel in the forward fragment variant (dFdx/dFdy), per
// shadel in the decoupled compute variant (from the triangle's barycentric
// derivatives). Materials sample with textureGrad in both, so the two variants
// run the same code on the same numbers.
// Part of the material SDK (framework/plugin/shaders/material.glsl).
#ifndef SG_SURFACE_GLSL
#define SG_SURFACE_GLSL

struct Surface {
  vec3 position;  // world
  vec3 normal;    // world, unit, facing the viewer for double-sided back faces
  vec4 tangent;   // world xyz, w = handedness
  vec2 uv0;
  vec2 uv1;
  vec4 color;     // COLOR_0
  vec2 uv0Dx, uv0Dy;  // derivatives of uv0 per sample step in x and y
  vec2 uv1Dx, uv1Dy;
  vec3 positionDx, positionDy;  // world position change per sample step
};

#endif
