#pragma once
// Detail-level selection and the filters' footprints, shared by shadel-mark
// (which marks the chunk whose tile holds a level's footprint) and composite
// (which reads them): both must run exactly this math, or composite reads shadels
// nobody marked. Mirrored by shaders/shadel_level.glsl.
#include <array>
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include <shadelgraph/shadel/level_rect.hpp>

namespace sg::shadel {

struct LevelSelection {
  float level = 0.0f;   // the fractional level, before clamping
  uint32_t fine = 0;    // floor(level), clamped to [0, levelCount - 1]
  uint32_t coarse = 0;  // fine + 1, clamped to levelCount - 1
  float blend = 0.0f;   // weight of `coarse`; 0 when coarse == fine
};

// dShadelDx/dShadelDy: the shading-UV derivatives per pixel in level-0
// shadels (dFdx(uv) * level0Size). The level is the isotropic one of the GL
// spec, log2 of the longer footprint axis, plus the global fractional bias
// (raised by the shade-space adjuster when storage fills). Zero and
// NaN derivatives give level 0, infinite ones the coarsest. levelCount >= 1.
// GLSL: sgSelectDetailLevel.
LevelSelection selectDetailLevel(glm::vec2 dShadelDx, glm::vec2 dShadelDy, float bias, uint32_t levelCount);

// The 2x2 bilinear taps of a level of `levelSize` shadels at a shading UV in
// [0,1]²: level-local shadels {lo.x, hi.x} x {lo.y, hi.y}, clamped to the
// level's edge (the chart does not wrap), and the weights of hi: the
// sample is clamped to the level's texel centres, so a clamped tap weighs 0
// and lo + 1 may stand in for hi (composite's tile read). uv *
// levelSize is exact in float (a power-of-two scale), so C++ and GLSL agree
// bit for bit. GLSL: sgBilinearTaps.
struct BilinearTaps {
  glm::uvec2 lo{0};
  glm::uvec2 hi{0};
  glm::vec2 weight{0.0f};
};
BilinearTaps bilinearTaps(glm::vec2 uv, uint32_t levelSize);

// The 8 virtual shadels a trilinear filter reads: 4 at the fine level, then
// 4 at the coarse one, each as (lo.x,lo.y), (hi.x,lo.y), (lo.x,hi.y),
// (hi.x,hi.y). `levels` is the instance's rectangles, indexed by level.
// GLSL: sgTrilinearShadel.
struct TrilinearFootprint {
  std::array<glm::uvec2, 8> shadels{};
  LevelSelection selection;
  glm::vec2 fineWeight{0.0f};    // bilinear weights at the fine level
  glm::vec2 coarseWeight{0.0f};  // and at the coarse level
};
TrilinearFootprint trilinearFootprint(glm::vec2 uv, const LevelSelection& selection, std::span<const LevelRect> levels);

// The composite filter; shadel-mark marks exactly its footprint. GLSL: SG_FILTER_*.
enum class CompositeFilter : int { Point = 0, Bilinear = 1, Trilinear = 2 };

// The level selection a filter uses. Trilinear: selectDetailLevel (fine =
// floor, blended towards coarse). Point and bilinear read one level: the
// nearest one, round(level) (GL's *_MIPMAP_NEAREST rule), so its shadel
// spacing is within a factor sqrt(2) of the pixel footprint's longer axis;
// floor would shade 1-4 shadels per pixel instead of 0.5-2. fine == coarse,
// blend 0. GLSL: sgSelectFilterLevel.
LevelSelection selectFilterLevel(CompositeFilter filter, glm::vec2 dShadelDx, glm::vec2 dShadelDy, float bias,
                                 uint32_t levelCount);

// The point filter's level-local shadel: the bilinear tap nearest the sample
// (weight >= 0.5 picks hi). GLSL: sgNearestTap.
glm::uvec2 nearestTap(const BilinearTaps& taps);

// The virtual shadels a filter reads: point 1 (fine level), bilinear 4 (fine
// level), trilinear 8, or 4 when the coarse level is the fine one.
// `selection`: selectFilterLevel's for the same filter. Composite reads each
// level's shadels from one chunk tile (the chunk and its one-shadel gutter,
// storedTexel): the tile of `tiles[i]`, the level's top-left tap, one per
// level read. shadel-mark marks exactly the chunks of `tiles`.
// GLSL: sgFootprintTileShadel.
struct FilterFootprint {
  std::array<glm::uvec2, 8> shadels{};
  uint32_t count = 0;
  std::array<glm::uvec2, 2> tiles{};
  uint32_t tileCount = 0;
};
FilterFootprint filterFootprint(CompositeFilter filter, glm::vec2 uv, const LevelSelection& selection,
                                std::span<const LevelRect> levels);

// Whether the tile of tileShadel's chunk (its 8x8 shadels, the next column
// and the next row) holds `shadel`.
bool inFootprintTile(glm::uvec2 tileShadel, glm::uvec2 shadel);

}  // namespace sg::shadel
