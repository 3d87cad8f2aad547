// Detail-level selection and the filters' footprints: the GLSL twin of
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

// Mirrors sg::shadel::levelFootprintSquared.
float sgLevelFootprintSquared(vec2 dShadelDx, vec2 dShadelDy, float maxAnisotropyLog2) {
  float longer = max(dot(dShadelDx, dShadelDx), dot(dShadelDy, dShadelDy));
  if (!(maxAnisotropyLog2 > 0.0)) return longer;
  float det = dShadelDx.x * dShadelDy.y - dShadelDx.y * dShadelDy.x;
  float minor = longer > 0.0 ? det * det / longer : 0.0;
  return max(longer * exp2(-2.0 * maxAnisotropyLog2), minor);
}

// An object's level rule (sg::shadel::LevelRule) is a pipeline variant of
// shadel-mark and composite: SG_LEVEL_RULE_ANISOTROPY_LOG2 and
// SG_LEVEL_RULE_BIAS (sg::shadel::levelRuleDefines), set only for objects
// with a rule. Without them the level is the isotropic one and the shaders
// are those of before the rule, so other objects pay nothing for it.
#ifdef SG_LEVEL_RULE_ANISOTROPY_LOG2
#define SG_LEVEL_FOOTPRINT_SQUARED(dx, dy) sgLevelFootprintSquared(dx, dy, SG_LEVEL_RULE_ANISOTROPY_LOG2)
#define SG_LEVEL_BIAS(bias) (bias + SG_LEVEL_RULE_BIAS)
#else
#define SG_LEVEL_FOOTPRINT_SQUARED(dx, dy) max(dot(dx, dx), dot(dy, dy))
#define SG_LEVEL_BIAS(bias) bias
#endif

// Mirrors sg::shadel::selectDetailLevel (with a level rule: its
// maxAnisotropyLog2 and the rule's bias added). dShadelDx/Dy: dFdx/dFdy of
// the shading UV times the instance's level0Size.
SgLevelSelection sgSelectDetailLevel(vec2 dShadelDx, vec2 dShadelDy, float bias, uint levelCount) {
  float rhoSquared = SG_LEVEL_FOOTPRINT_SQUARED(dShadelDx, dShadelDy);
  SgLevelSelection selection;
  selection.level = 0.5 * log2(max(rhoSquared, 1e-20)) + SG_LEVEL_BIAS(bias);
  float clamped = selection.level;
  if (!(clamped >= 0.0)) clamped = 0.0;
  clamped = min(clamped, float(levelCount - 1u));
  selection.fine = uint(floor(clamped));
  selection.coarse = min(selection.fine + 1u, levelCount - 1u);
  selection.blend = selection.coarse == selection.fine ? 0.0 : clamped - float(selection.fine);
  return selection;
}

// The composite filter, which also decides what shadel-mark marks:
// sg::shadel::CompositeFilter. Both passes are compiled with SG_FILTER set
// from the one DecoupledFrame::filter (passes::filterDefine).
const uint SG_FILTER_POINT = 0u;      // the nearest shadel of the nearest level
const uint SG_FILTER_BILINEAR = 1u;   // the 2x2 taps of the nearest level
const uint SG_FILTER_TRILINEAR = 2u;  // the 2x2 taps of the fine and of the coarse level

// Mirrors sg::shadel::selectFilterLevel: trilinear as sgSelectDetailLevel;
// point and bilinear the nearest level (round), in `fine` and `coarse`.
SgLevelSelection sgSelectFilterLevel(uint compositeFilter, vec2 dShadelDx, vec2 dShadelDy, float bias, uint levelCount) {
  SgLevelSelection selection = sgSelectDetailLevel(dShadelDx, dShadelDy, bias, levelCount);
  if (compositeFilter == SG_FILTER_TRILINEAR) return selection;
  selection.fine = selection.blend >= 0.5 ? selection.coarse : selection.fine;
  selection.coarse = selection.fine;
  selection.blend = 0.0;
  return selection;
}

// sg::shadel::BilinearTaps: level-local shadels {lo.x, hi.x} x {lo.y, hi.y}.
struct SgBilinearTaps {
  uvec2 lo;
  uvec2 hi;
  vec2 weight;  // of hi
};

// Mirrors sg::shadel::bilinearTaps. uv: shading UV in [0,1]² (tileOffset
// already subtracted). The sample is clamped to the level's texel centres,
// so a tap clamped at the edge (hi == lo) weighs nothing.
SgBilinearTaps sgBilinearTaps(vec2 uv, uint levelSize) {
  float size = float(levelSize);
  vec2 p = clamp(uv * size - 0.5, vec2(0.0), vec2(size - 1.0));
  vec2 base = floor(p);
  SgBilinearTaps taps;
  taps.lo = uvec2(base);
  taps.hi = min(taps.lo + 1u, uvec2(levelSize - 1u));
  taps.weight = p - base;
  return taps;
}

// Mirrors one element of sg::shadel::trilinearFootprint().shadels: tap
// i in 0..3 at `rect` (the fine or the coarse level's rectangle), ordered
// (lo,lo), (hi,lo), (lo,hi), (hi,hi).
uvec2 sgFootprintShadel(SgLevelRect rect, SgBilinearTaps taps, uint i) {
  return rect.origin + uvec2((i & 1u) != 0u ? taps.hi.x : taps.lo.x, (i & 2u) != 0u ? taps.hi.y : taps.lo.y);
}

// Mirrors sg::shadel::nearestTap: the point filter's level-local shadel, the
// bilinear tap nearest the sample (one of lo/hi per axis).
uvec2 sgNearestTap(SgBilinearTaps taps) {
  return uvec2(taps.weight.x >= 0.5 ? taps.hi.x : taps.lo.x, taps.weight.y >= 0.5 ? taps.hi.y : taps.lo.y);
}

// Mirrors sg::shadel::FilterFootprint::tiles: a level's footprint is read
// from one chunk tile, the one of its top-left tap (shade storage keeps a
// one-shadel gutter right of and below each chunk, sgStoredTexel), at
// (tile shadel & 7) + {0,1}². shadel-mark marks that chunk, composite looks
// it up once.
uvec2 sgFootprintTileShadel(SgLevelRect rect, SgBilinearTaps taps) { return rect.origin + taps.lo; }

#endif
