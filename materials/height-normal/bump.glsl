// Bump mapping from a height's change per sample step (Mikkelsen 2010,
// "Bump Mapping Unparametrized Surfaces on the GPU"): the perturbed normal
// from the surface's position derivatives and the height differences along
// the same steps. Both variants use it: per shadel from neighbours, per pixel
// from dFdx/dFdy.
#ifndef SG_BUMP_GLSL
#define SG_BUMP_GLSL

#include <materials/gltf-pbr/gltf_pbr.glsl>

vec3 bumpedNormal(Surface s, float dHeightDx, float dHeightDy) {
  vec3 r1 = cross(s.positionDy, s.normal), r2 = cross(s.normal, s.positionDx);
  float det = dot(s.positionDx, r1);
  if (abs(det) < 1e-20) return s.normal;
  vec3 gradient = sign(det) * (dHeightDx * r1 + dHeightDy * r2);
  return normalize(abs(det) * s.normal - gradient);
}

// The glTF material lit with the bumped normal.
vec4 shadeBumped(Surface s, float dHeightDx, float dHeightDy) {
  s.normal = bumpedNormal(s, dHeightDx, dHeightDy);
  return shadeGltfPbr(s);
}

#endif
