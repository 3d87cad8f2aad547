// The surface point a material shades, with the derivatives of its UVs per
// screen pixel in both variants: dFdx/dFdy in the forward fragment variant,
// projected at the shadel in the decoupled compute variant (the shadel step's
// derivatives through the screen's Jacobian, sgUvDerivativesPerPixel), so a
// texture is filtered at the pixel's footprint either way; and the position
// derivatives per sample step (pixel or shadel: what bump mapping pairs with
// neighbour differences). Materials sample with textureGrad in both, so the
// two variants run the same code on the same numbers.
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
  vec2 uv0Dx, uv0Dy;  // derivatives of uv0 per screen pixel in x and y
  vec2 uv1Dx, uv1Dy;
  vec3 positionDx, positionDy;  // world position change per sample step
};

#endif
