// Layer "height": a field of round bumps on uv0, in world units (R16F).
// Parameters: BUMP_FREQUENCY (bumps per UV unit), BUMP_HEIGHT (world units).
#ifndef SG_HEIGHT_LAYER_GLSL
#define SG_HEIGHT_LAYER_GLSL

vec4 bumpHeight(Surface s) {
  vec2 cell = fract(s.uv0 * BUMP_FREQUENCY) - 0.5;
  float dome = clamp(1.0 - 4.0 * dot(cell, cell), 0.0, 1.0);
  return vec4(BUMP_HEIGHT * dome * dome, 0.0, 0.0, 0.0);
}

#endif
