// The depth pre-pass pays below kZPrepassMaxTrianglesPerPixel opaque
// triangles per output pixel, and not above (z_prepass_rule.hpp).
#include <gtest/gtest.h>

#include <z-prepass/z_prepass_rule.hpp>

namespace sg::passes {
namespace {

constexpr uint64_t k720p = 1280 * 720;

TEST(ZPrepassRule, PaysForLargeTriangles) {
  EXPECT_TRUE(zPrepassPays(12'000, k720p));  // a few thousand triangles filling the screen (the courtyard)
}

TEST(ZPrepassRule, DoesNotPayWhereTrianglesOutnumberPixels) {
  EXPECT_FALSE(zPrepassPays(1'040'000, k720p));  // MetalRoughSpheresNoTextures
  EXPECT_FALSE(zPrepassPays(1'040'000, 640 * 360));
}

// The models the threshold was measured on (docs/benchmarks.md, "Depth pre-pass only where it pays").
TEST(ZPrepassRule, MeasuredModelsGoTheWayTheyMeasured) {
  constexpr uint64_t k360p = 640 * 360;
  EXPECT_TRUE(zPrepassPays(121'496, k360p));    // 2CylinderEngine: 1.18x slower without
  EXPECT_TRUE(zPrepassPays(121'496, k720p));    // 1.38x slower without
  EXPECT_FALSE(zPrepassPays(198'470, k360p));   // ReciprocatingSaw: 0.70x without
  EXPECT_TRUE(zPrepassPays(198'470, k720p));    // 1.09x slower without
  EXPECT_FALSE(zPrepassPays(1'040'000, k720p));  // MetalRoughSpheresNoTextures: 0.66x without
}

TEST(ZPrepassRule, TheThresholdIsTrianglesPerPixel) {
  const auto at = uint64_t(kZPrepassMaxTrianglesPerPixel * double(k720p));
  EXPECT_TRUE(zPrepassPays(at - 1, k720p));
  EXPECT_FALSE(zPrepassPays(at, k720p));
  // The same triangles on a quarter of the pixels cover four times the share.
  EXPECT_TRUE(zPrepassPays(at / 2, k720p));
  EXPECT_FALSE(zPrepassPays(at / 2, k720p / 4));
}

TEST(ZPrepassRule, NoPixelsNoPrepass) { EXPECT_FALSE(zPrepassPays(10, 0)); }

}  // namespace
}  // namespace sg::passes
