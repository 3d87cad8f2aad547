// Detail-level selection and trilinear footprint: the GLSL twin of
// framework/shadel/level_selection.hpp/.cpp. shadel-mark and composite must
// both call these, so every shadel composite reads was marked.
#ifndef SG_SHADEL_LEVEL_GLSL
#define SG_SHADEL_LEVEL_GLSL

#include "shadel_address.glsl"

// sg::shadel::LevelSelection.
struct SgLevelSelection {
  float level;   // fractional, before clamping
  uint fine;     // floor(level) clamped to [0, levelCount - 1]
  uint coarse;   // fine + 1 clamped to levelCount - 1
  float blend;   // weight of coarse; 0 when coarse == fine
};

// Mirrors sg::shadel::selectDetailLevel. dShadelDx/Dy: dFdx/dFdy of the
// shading UV times the instance's level0Size.
SgLevelSelection sgSelectDetailLevel(vec2 dShadelDx, vec2 dShadelDy, float bias, uint levelCount) {
  float rhoSquared = max(dot(dShadelDx, dShadelDx), dot(dShadelDy, dShadelDy));
  SgLevelSelection selection;
  selection.level = 0.5 * log2(max(rhoSquared, 1e-20)) + bias;
  float clamped = selection.level;
  if (!(clamped >= 0.0)) clamped = 0.0;
  clamped = min(clamped, float(levelCount - 1u));
  selection.fine = uint(floor(clamped));
  selection.coarse = min(selection.fine + 1u, levelCount - 1u);
  selection.blend = selection.coarse == selection.fine ? 0.0 : clamped - float(selection.fine);
  return selection;
}

// sg::shadel::BilinearTaps: level-local shadels {lo.x, hi.x} x {lo.y, hi.y}.
struct SgBilinearTaps {
  uvec2 lo;
  uvec2 hi;
  vec2 weight;  // of hi
};

// Mirrors sg::shadel::bilinearTaps. uv: shading UV in [0,1]² (tileOffset
// already subtracted).
SgBilinearTaps sgBilinearTaps(vec2 uv, uint levelSize) {
  float size = float(levelSize);
  vec2 p = uv * size - 0.5;
  vec2 base = floor(p);
  SgBilinearTaps taps;
  taps.lo = uvec2(clamp(base, vec2(0.0), vec2(size - 1.0)));
  taps.hi = uvec2(clamp(base + 1.0, vec2(0.0), vec2(size - 1.0)));
  taps.weight = clamp(p - base, vec2(0.0), vec2(1.0));
  return taps;
}

// Mirrors one element of sg::shadel::trilinearFootprint().shadels: tap
// i in 0..3 at `rect` (the fine or the coarse level's rectangle), ordered
// (lo,lo), (hi,lo), (lo,hi), (hi,hi).
uvec2 sgFootprintShadel(SgLevelRect rect, SgBilinearTaps taps, uint i) {
  return rect.origin + uvec2((i & 1u) != 0u ? taps.hi.x : taps.lo.x, (i & 2u) != 0u ? taps.hi.y : taps.lo.y);
}

#endif
