// Detail-level selection and the trilinear footprint.
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/level_selection.hpp>
#include <shadelgraph/shadel/shadel_address.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>

namespace sg::shadel {
namespace {

TEST(LevelSelection, KnownDerivativesGiveKnownLevels) {
  // One level-0 shadel per pixel: level 0.
  LevelSelection s = selectDetailLevel({1, 0}, {0, 1}, 0.0f, 9);
  EXPECT_FLOAT_EQ(s.level, 0.0f);
  EXPECT_EQ(s.fine, 0u);
  EXPECT_EQ(s.coarse, 1u);
  EXPECT_FLOAT_EQ(s.blend, 0.0f);
  // Four shadels per pixel along y (the longer axis decides): level 2.
  s = selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9);
  EXPECT_FLOAT_EQ(s.level, 2.0f);
  EXPECT_EQ(s.fine, 2u);
  EXPECT_EQ(s.coarse, 3u);
  // Diagonal footprint: length 3 -> log2(3).
  s = selectDetailLevel({3.0f / std::sqrt(2.0f), 3.0f / std::sqrt(2.0f)}, {0, 1}, 0.0f, 9);
  EXPECT_NEAR(s.level, std::log2(3.0f), 1e-5f);
  EXPECT_EQ(s.fine, 1u);
  EXPECT_EQ(s.coarse, 2u);
  EXPECT_NEAR(s.blend, std::log2(3.0f) - 1.0f, 1e-5f);
}

TEST(LevelSelection, AnisotropyLimitFollowsTheMinorAxisUpToKLevels) {
  // Four shadels per pixel along y, one along x (anisotropy 4, two levels):
  // the isotropic rule says level 2; each level of allowed anisotropy takes
  // one off, down to the minor axis's level 0.
  EXPECT_FLOAT_EQ(selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9).level, 2.0f);
  EXPECT_FLOAT_EQ(selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9, 0.0f).level, 2.0f);
  EXPECT_FLOAT_EQ(selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9, 0.5f).level, 1.5f);
  EXPECT_FLOAT_EQ(selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9, 1.0f).level, 1.0f);
  EXPECT_FLOAT_EQ(selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9, 2.0f).level, 0.0f);
  EXPECT_FLOAT_EQ(selectDetailLevel({1, 0}, {0, 4}, 0.0f, 9, 3.0f).level, 0.0f);  // never finer than the minor axis
  // A sheared footprint whose two derivatives are both long (4 and sqrt(17))
  // but which is thin (|det| = 4: minor axis 4 / sqrt(17)): the shorter of
  // the two derivatives would say level 2, the minor axis about 0.
  EXPECT_NEAR(std::sqrt(levelFootprintSquared({4, 0}, {4, 1}, 8.0f)), 4.0f / std::sqrt(17.0f), 1e-5f);
  EXPECT_NEAR(selectDetailLevel({4, 0}, {4, 1}, 0.0f, 9, 1.0f).level, std::log2(std::sqrt(17.0f) / 2.0f), 1e-5f);
  // Isotropic footprints (any rotation): every limit gives the same level.
  const glm::vec2 dx{3.0f * std::cos(0.3f), 3.0f * std::sin(0.3f)}, dy{-3.0f * std::sin(0.3f), 3.0f * std::cos(0.3f)};
  EXPECT_NEAR(selectDetailLevel(dx, dy, 0.0f, 9, 2.0f).level, selectDetailLevel(dx, dy, 0.0f, 9).level, 1e-5f);
  // A footprint with no area (a line) is k levels below its length, not level 0.
  EXPECT_NEAR(selectDetailLevel({5, 0}, {10, 0}, 0.0f, 9, 1.0f).level, std::log2(5.0f), 1e-5f);
  const LevelSelection zero = selectDetailLevel({0, 0}, {0, 0}, 0.0f, 9, 1.0f);
  EXPECT_EQ(zero.fine, 0u);
  EXPECT_EQ(zero.blend, 0.0f);
  EXPECT_EQ(selectDetailLevel({NAN, 0}, {0, 1}, 0.0f, 9, 1.0f).fine, 0u);
  // The filters' nearest level follows the limit too.
  EXPECT_EQ(selectFilterLevel(CompositeFilter::Bilinear, {1, 0}, {0, 6}, 0.0f, 9).fine, 3u);  // round(2.58)
  EXPECT_EQ(selectFilterLevel(CompositeFilter::Bilinear, {1, 0}, {0, 6}, 0.0f, 9, 1.0f).fine, 2u);  // round(1.58)
}

TEST(LevelSelection, LevelRulePacksIntoOneWord) {
  EXPECT_EQ(packLevelRule({}), 0u);  // the default: what a zero-filled record means
  for (const LevelRule rule : {LevelRule{1.0f, 0.0f}, LevelRule{0.5f, -0.5f}, LevelRule{2.25f, 0.75f}}) {
    const LevelRule back = unpackLevelRule(packLevelRule(rule));
    EXPECT_EQ(back.maxAnisotropyLog2, rule.maxAnisotropyLog2);
    EXPECT_EQ(back.bias, rule.bias);
  }
  EXPECT_EQ(unpackLevelRule(packLevelRule(kUnmipmappedLevelRule)).maxAnisotropyLog2, kUnmipmappedLevelRule.maxAnisotropyLog2);
}

TEST(LevelSelection, LevelRuleDefinesAreFloatLiteralsOnlyForARule) {
  EXPECT_TRUE(levelRuleDefines({}).empty());  // no variant: the shaders of before the rule
  const auto defines = levelRuleDefines({.maxAnisotropyLog2 = 1.0f, .bias = -0.375f});
  ASSERT_EQ(defines.size(), 2u);
  EXPECT_EQ(defines[0].first, "SG_LEVEL_RULE_ANISOTROPY_LOG2");
  EXPECT_EQ(defines[1].first, "SG_LEVEL_RULE_BIAS");
  for (const auto& [name, literal] : defines)  // GLSL reads a float only with a point or exponent
    EXPECT_NE(literal.find_first_of(".e"), std::string::npos) << name << " " << literal;
  EXPECT_EQ(std::strtof(defines[0].second.c_str(), nullptr), 1.0f);
  EXPECT_EQ(std::strtof(defines[1].second.c_str(), nullptr), -0.375f);
  EXPECT_EQ(levelRuleDefines({.maxAnisotropyLog2 = 0.0f, .bias = 0.25f}).size(), 2u);  // a bias alone is a rule
}

TEST(LevelSelection, BiasShiftsTheLevel) {
  const LevelSelection base = selectDetailLevel({2, 0}, {0, 2}, 0.0f, 9);
  const LevelSelection up = selectDetailLevel({2, 0}, {0, 2}, 0.25f, 9);
  const LevelSelection more = selectDetailLevel({2, 0}, {0, 2}, 1.5f, 9);
  const LevelSelection down = selectDetailLevel({2, 0}, {0, 2}, -0.5f, 9);
  EXPECT_FLOAT_EQ(base.level, 1.0f);
  EXPECT_FLOAT_EQ(up.level, 1.25f);
  EXPECT_EQ(up.fine, 1u);
  EXPECT_FLOAT_EQ(up.blend, 0.25f);
  EXPECT_EQ(more.fine, 2u);
  EXPECT_FLOAT_EQ(more.blend, 0.5f);
  EXPECT_EQ(down.fine, 0u);
  EXPECT_FLOAT_EQ(down.blend, 0.5f);
}

TEST(LevelSelection, ClampsAtBothEnds) {
  // Magnified (less than a shadel per pixel): level 0, no blend.
  LevelSelection s = selectDetailLevel({0.1f, 0}, {0, 0.1f}, 0.0f, 5);
  EXPECT_LT(s.level, 0.0f);
  EXPECT_EQ(s.fine, 0u);
  EXPECT_FLOAT_EQ(s.blend, 0.0f);
  // Past the coarsest level: both taps there.
  s = selectDetailLevel({1000, 0}, {0, 1}, 0.0f, 5);
  EXPECT_EQ(s.fine, 4u);
  EXPECT_EQ(s.coarse, 4u);
  EXPECT_FLOAT_EQ(s.blend, 0.0f);
  // Zero derivatives (a zero-UV-area triangle) and non-finite ones: level 0.
  s = selectDetailLevel({0, 0}, {0, 0}, 0.3f, 5);
  EXPECT_EQ(s.fine, 0u);
  s = selectDetailLevel({NAN, 0}, {0, 0}, 0.0f, 5);
  EXPECT_EQ(s.fine, 0u);
  s = selectDetailLevel({INFINITY, 0}, {0, 0}, 0.0f, 5);
  EXPECT_EQ(s.fine, 4u);
  // A single level.
  s = selectDetailLevel({8, 0}, {0, 8}, 0.0f, 1);
  EXPECT_EQ(s.fine, 0u);
  EXPECT_EQ(s.coarse, 0u);
}

// Point and bilinear read the nearest level, so its shadel spacing is within
// sqrt(2) of the pixel footprint's longer axis; trilinear keeps floor + blend.
TEST(LevelSelection, OneLevelFiltersTakeTheNearestLevel) {
  struct Case {
    float shadelsPerPixel;
    uint32_t nearest;
  };
  for (const Case c : {Case{1.0f, 0u}, Case{1.41f, 0u}, Case{1.42f, 1u}, Case{2.0f, 1u}, Case{2.82f, 1u},
                       Case{2.83f, 2u}, Case{0.2f, 0u}, Case{1000.0f, 4u}}) {
    for (CompositeFilter filter : {CompositeFilter::Point, CompositeFilter::Bilinear}) {
      const LevelSelection s = selectFilterLevel(filter, {c.shadelsPerPixel, 0}, {0, 0.5f}, 0.0f, 5);
      EXPECT_EQ(s.fine, c.nearest) << c.shadelsPerPixel << " shadels per pixel";
      EXPECT_EQ(s.coarse, s.fine);
      EXPECT_FLOAT_EQ(s.blend, 0.0f);
    }
    const LevelSelection trilinear = selectFilterLevel(CompositeFilter::Trilinear, {c.shadelsPerPixel, 0}, {0, 0.5f}, 0.0f, 5);
    const LevelSelection detail = selectDetailLevel({c.shadelsPerPixel, 0}, {0, 0.5f}, 0.0f, 5);
    EXPECT_EQ(trilinear.fine, detail.fine);
    EXPECT_EQ(trilinear.coarse, detail.coarse);
    EXPECT_FLOAT_EQ(trilinear.blend, detail.blend);
  }
  // The bias moves the rounding point: +0.5 turns 1.2 shadels per pixel (level 0.26) into level 1.
  EXPECT_EQ(selectFilterLevel(CompositeFilter::Bilinear, {1.2f, 0}, {0, 1}, 0.0f, 5).fine, 0u);
  EXPECT_EQ(selectFilterLevel(CompositeFilter::Bilinear, {1.2f, 0}, {0, 1}, 0.5f, 5).fine, 1u);
  // A single level.
  EXPECT_EQ(selectFilterLevel(CompositeFilter::Bilinear, {8, 0}, {0, 8}, 0.0f, 1).fine, 0u);
}

TEST(BilinearTaps, TexelCentresAndEdges) {
  // The centre of texel (3, 5) of an 8x8 level: that texel, zero weight.
  BilinearTaps taps = bilinearTaps({3.5f / 8, 5.5f / 8}, 8);
  EXPECT_EQ(taps.lo, glm::uvec2(3, 5));
  EXPECT_EQ(taps.hi, glm::uvec2(4, 6));
  EXPECT_EQ(taps.weight, glm::vec2(0.0f));
  // Half way between texel centres.
  taps = bilinearTaps({4.0f / 8, 1.0f / 8}, 8);
  EXPECT_EQ(taps.lo, glm::uvec2(3, 0));
  EXPECT_EQ(taps.weight, glm::vec2(0.5f));
  // The chart's edges clamp instead of wrapping: the sample moves to the
  // edge texel's centre, so a tap past it weighs nothing.
  taps = bilinearTaps({0.0f, 1.0f}, 8);
  EXPECT_EQ(taps.lo, glm::uvec2(0, 7));
  EXPECT_EQ(taps.hi, glm::uvec2(1, 7));
  EXPECT_EQ(taps.weight, glm::vec2(0.0f));
  taps = bilinearTaps({-0.01f, 1.01f}, 8);
  EXPECT_EQ(taps.lo, glm::uvec2(0, 7));
  EXPECT_EQ(taps.hi, glm::uvec2(1, 7));
  EXPECT_EQ(taps.weight, glm::vec2(0.0f));
  // A one-shadel level.
  taps = bilinearTaps({0.7f, 0.2f}, 1);
  EXPECT_EQ(taps.lo, glm::uvec2(0));
  EXPECT_EQ(taps.hi, glm::uvec2(0));
  EXPECT_EQ(taps.weight, glm::vec2(0.0f));
}

TEST(TrilinearFootprint, StaysInsideTheInstanceLevels) {
  ShadelSpace space;
  ASSERT_TRUE(space.allocate(0, makeDetailLevels(512)).ok());  // neighbours, to make escapes visible
  const AllocationResult result = space.allocate(1, makeDetailLevels(2048));
  ASSERT_TRUE(result.ok());
  const InstanceShadels& instance = *result.instance;
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> uvDistribution(-0.02f, 1.02f), logDistribution(-3.0f, 12.0f),
      angle(0.0f, 6.2831853f), biasDistribution(-0.5f, 1.5f);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec2 uv(uvDistribution(rng), uvDistribution(rng));
    const float length = std::exp2(logDistribution(rng)), a = angle(rng);
    const glm::vec2 dx = length * glm::vec2(std::cos(a), std::sin(a));
    const glm::vec2 dy = 0.5f * length * glm::vec2(-std::sin(a), std::cos(a));
    const LevelSelection selection = selectDetailLevel(dx, dy, biasDistribution(rng), instance.levels.levelCount);
    ASSERT_LT(selection.fine, instance.levels.levelCount);
    ASSERT_LT(selection.coarse, instance.levels.levelCount);
    ASSERT_LE(selection.coarse - selection.fine, 1u);
    const TrilinearFootprint footprint = trilinearFootprint(uv, selection, instance.rects);
    for (size_t k = 0; k < 8; ++k) {
      const LevelRect& rect = instance.rects[k < 4 ? selection.fine : selection.coarse];
      const glm::uvec2 shadel = footprint.shadels[k];
      ASSERT_GE(shadel.x, rect.origin.x);
      ASSERT_GE(shadel.y, rect.origin.y);
      ASSERT_LT(shadel.x, rect.origin.x + rect.size) << "uv " << uv.x << " level size " << rect.size;
      ASSERT_LT(shadel.y, rect.origin.y + rect.size);
    }
  }
}

TEST(FilterFootprint, PointAndBilinearAreInsideTrilinear) {
  const LevelRect levels[] = {{{0, 0}, 64, 64}, {{64, 0}, 32, 32}};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uvDistribution(-0.02f, 1.02f), blend(0.0f, 1.0f);
  for (int i = 0; i < 5000; ++i) {
    const glm::vec2 uv(uvDistribution(rng), uvDistribution(rng));
    const LevelSelection selection{0.5f, 0, 1, blend(rng)};
    const TrilinearFootprint trilinear = trilinearFootprint(uv, selection, levels);
    const FilterFootprint point = filterFootprint(CompositeFilter::Point, uv, selection, levels);
    const FilterFootprint bilinear = filterFootprint(CompositeFilter::Bilinear, uv, selection, levels);
    const FilterFootprint all = filterFootprint(CompositeFilter::Trilinear, uv, selection, levels);
    ASSERT_EQ(point.count, 1u);
    ASSERT_EQ(bilinear.count, 4u);
    ASSERT_EQ(all.count, 8u);
    // The nearest tap is one of the bilinear taps, the one of the largest weight.
    const glm::vec2 w = trilinear.fineWeight;
    const uint32_t nearest = (w.x >= 0.5f ? 1u : 0u) | (w.y >= 0.5f ? 2u : 0u);
    ASSERT_EQ(point.shadels[0], trilinear.shadels[nearest]);
    for (uint32_t k = 0; k < 8; ++k) ASSERT_EQ(all.shadels[k], trilinear.shadels[k]);
    for (uint32_t k = 0; k < 4; ++k) ASSERT_EQ(bilinear.shadels[k], trilinear.shadels[k]);
  }
  // One level: trilinear reads the fine level only.
  const LevelSelection single{0.0f, 1, 1, 0.0f};
  EXPECT_EQ(filterFootprint(CompositeFilter::Trilinear, {0.3f, 0.6f}, single, levels).count, 4u);
}

// Composite reads each level's footprint from one chunk tile (the chunk and
// its one-shadel gutter): the tile of the chunk shadel-mark marks. Across
// chunk and entry edges, at level edges and for levels smaller than a chunk.
TEST(FilterFootprint, EveryTapIsInTheMarkedChunksTile) {
  const LevelRect levels[] = {{{4096, 0}, 128, 128}, {{4224, 64}, 64, 64}, {{4288, 72}, 4, 8}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uvDistribution(-0.02f, 1.02f), blend(0.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) {
    const glm::vec2 uv(uvDistribution(rng), uvDistribution(rng));
    const uint32_t fine = rng() % 3;
    const LevelSelection selection{float(fine), fine, std::min(fine + 1, 2u), fine == 2 ? 0.0f : blend(rng)};
    for (CompositeFilter filter : {CompositeFilter::Point, CompositeFilter::Bilinear, CompositeFilter::Trilinear}) {
      const FilterFootprint footprint = filterFootprint(filter, uv, selection, levels);
      const bool twoLevels = filter == CompositeFilter::Trilinear && selection.coarse != selection.fine;
      ASSERT_EQ(footprint.tileCount, twoLevels ? 2u : 1u);
      for (uint32_t k = 0; k < footprint.count; ++k) {
        const uint32_t tile = k < 4 ? 0 : 1;
        ASSERT_TRUE(inFootprintTile(footprint.tiles[tile], footprint.shadels[k]))
            << "uv " << uv.x << "," << uv.y << " level " << (tile ? selection.coarse : selection.fine);
      }
    }
  }
  // The tile is the chunk's 9x9: its own 8x8, the next column and row.
  EXPECT_TRUE(inFootprintTile({71, 7}, {72, 8}));
  EXPECT_TRUE(inFootprintTile({64, 0}, {64, 0}));
  EXPECT_FALSE(inFootprintTile({71, 7}, {73, 7}));
  EXPECT_FALSE(inFootprintTile({71, 8}, {71, 7}));
}

}  // namespace
}  // namespace sg::shadel
