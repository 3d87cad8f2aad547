// Detail-level selection and the trilinear footprint.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/level_selection.hpp>
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
  // The chart's edges clamp instead of wrapping.
  taps = bilinearTaps({0.0f, 1.0f}, 8);
  EXPECT_EQ(taps.lo, glm::uvec2(0, 7));
  EXPECT_EQ(taps.hi, glm::uvec2(0, 7));
  taps = bilinearTaps({-0.01f, 1.01f}, 8);
  EXPECT_EQ(taps.lo, glm::uvec2(0, 7));
  EXPECT_EQ(taps.hi, glm::uvec2(0, 7));
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

}  // namespace
}  // namespace sg::shadel
