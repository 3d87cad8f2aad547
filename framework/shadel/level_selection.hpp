#pragma once
// Detail-level selection and the filters' footprints, shared by shadel-mark
// (which marks the chunk whose tile holds a level's footprint) and composite
// (which reads them): both must run exactly this math, or composite reads shadels
// nobody marked. Mirrored by shaders/shadel_level.glsl.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/shadel/level_rect.hpp>

namespace sg::shadel {

struct LevelSelection {
  float level = 0.0f;   // the fractional level, before clamping
  uint32_t fine = 0;    // floor(level), clamped to [0, levelCount - 1]
  uint32_t coarse = 0;  // fine + 1, clamped to levelCount - 1
  float blend = 0.0f;   // weight of `coarse`; 0 when coarse == fine
};

// How an object's level follows its pixel footprint (SgDecoupledObject.levelRule,
// packed as two halves). maxAnisotropyLog2 k: the level follows the footprint's
// minor axis (|det J| / the longer derivative) down to k levels below the
// longer derivative's (EXT_texture_filter_anisotropic's lambda with max
// anisotropy 2^k); 0 is the isotropic GL rule. bias: added to the global bias.
// The default (0, 0) is every object's rule but kUnmipmappedLevelRule's and
// kResampledTextureLevelRule's.
struct LevelRule {
  float maxAnisotropyLog2 = 0.0f;
  float bias = 0.0f;
};
// The rule of objects whose material samples a texture without mip levels
// (scene::samplesUnmipmappedTexture). Forward reads such a texture at every
// pixel unfiltered, so its image holds detail at the pixel's rate in every
// direction; the isotropic nearest level shades up to sqrt(2) pixels apart
// along the footprint's longer axis and loses it. Anisotropy up to 2 (k = 1),
// chosen by measurement: MorphPrimitivesTest then lands closer than forward
// to a 16-sample reference at 640x360 and 1280x720 with 1.17 shadels per
// covered pixel; k = 1.5 is 1.48 (docs/decoupled-shading.md, "Unmipmapped
// textures").
inline constexpr LevelRule kUnmipmappedLevelRule{.maxAnisotropyLog2 = 1.0f, .bias = 0.0f};
// The rule of objects shaded in an automatic chart whose material samples a
// texture. Their shadels sample the texture off its texel grid and composite
// resamples them again, so a texel-wide line is blurred twice (in the mesh's
// own UVs, with level 0 at the texture's density, a level's shadels sit on
// the texel centres of a mip level, and composite's bilinear is the
// texture's own). The bias moves point's and bilinear's rounding from 0.5 to
// 0.625: shadels 0.65-1.30 pixels apart instead of 0.71-1.41. DamagedHelmet
// at 640x360 then reaches 40.1 dB against forward instead of 39.3 at 1.30
// shadels per covered pixel; the same bias on every object put three
// mipmapped text quads of TextureTransformTest at 1.98 (docs/decoupled-
// shading.md, "Resampled textures: a finer level rounding").
inline constexpr LevelRule kResampledTextureLevelRule{.maxAnisotropyLog2 = 0.0f, .bias = -0.125f};

// Half floats in one uint (low: maxAnisotropyLog2, high: bias), as GLSL's
// packHalf2x16: exact for quarter steps (DecoupledFrame::levelRules).
uint32_t packLevelRule(LevelRule rule);
LevelRule unpackLevelRule(uint32_t packed);

// The defines of shadel_level.glsl's variant for `rule`, as float literals:
// SG_LEVEL_RULE_ANISOTROPY_LOG2 and SG_LEVEL_RULE_BIAS; none for the default
// rule, whose shaders are those of before the rule.
std::vector<std::pair<std::string, std::string>> levelRuleDefines(LevelRule rule);

// The squared footprint length the level is log2 of (in level-0 shadels):
// max(longer² / 4^k, minor²). GLSL: sgLevelFootprintSquared.
float levelFootprintSquared(glm::vec2 dShadelDx, glm::vec2 dShadelDy, float maxAnisotropyLog2);

// dShadelDx/dShadelDy: the shading-UV derivatives per pixel in level-0
// shadels (dFdx(uv) * level0Size). The level is the isotropic one of the GL
// spec, log2 of the longer footprint axis, plus the global fractional bias
// (raised by the shade-space adjuster when storage fills). Zero and
// NaN derivatives give level 0, infinite ones the coarsest. levelCount >= 1.
// GLSL: sgSelectDetailLevel.
// maxAnisotropyLog2: LevelRule's (0: the longer axis).
LevelSelection selectDetailLevel(glm::vec2 dShadelDx, glm::vec2 dShadelDy, float bias, uint32_t levelCount,
                                 float maxAnisotropyLog2 = 0.0f);

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
                                 uint32_t levelCount, float maxAnisotropyLog2 = 0.0f);

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
