// The depth pre-pass pays where the overdraw it removes outweighs drawing the
// triangles again (z_prepass_rule.hpp), and a measurement goes stale with the
// size, the visible triangles or the camera.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <z-prepass/z_prepass_rule.hpp>

namespace sg::passes {
namespace {

TEST(ZPrepassRule, PaysWhereOverdrawOutweighsTheTrianglesDrawnAgain) {
  // The default scene at 1280x720: 7k large triangles, 23 overdrawn fragments each.
  EXPECT_TRUE(zPrepassPays({.triangles = 7'344, .depthPassed = 852'676, .shaded = 681'829}));
  // MetalRoughSpheresNoTextures at 1280x720: no overdraw at all (closed surfaces lose their back faces).
  EXPECT_FALSE(zPrepassPays({.triangles = 1'040'409, .depthPassed = 113'908, .shaded = 113'907}));
}

// Counts of the measurement frame at each size (`render --stats`, z_prepass.overdraw)
// and which way callgrind said (instructions a frame, docs/benchmarks.md "Depth pre-pass").
TEST(ZPrepassRule, MeasuredModelsGoTheWayCallgrindMeasured) {
  // 2CylinderEngine at 1280x720: 3.1 overdrawn a triangle, 8% more instructions without.
  EXPECT_TRUE(zPrepassPays({.triangles = 121'496, .depthPassed = 693'423, .shaded = 315'199}));
  // At 640x360: 0.78 a triangle, 8% fewer without.
  EXPECT_FALSE(zPrepassPays({.triangles = 121'496, .depthPassed = 173'366, .shaded = 78'806}));
  // ReciprocatingSaw at 1280x720 (0.22 triangles a pixel, which the old rule kept it for): 0.66 a triangle.
  EXPECT_FALSE(zPrepassPays({.triangles = 198'470, .depthPassed = 278'643, .shaded = 148'315}));
  EXPECT_FALSE(zPrepassPays({.triangles = 198'470, .depthPassed = 69'663, .shaded = 37'074}));  // 640x360
}

// DamagedHelmet at 1280x720: 1.26 overdrawn a triangle, each fragment sampling
// five textures: forward-opaque shades the overdraw at several times the pre-pass's cost.
TEST(ZPrepassRule, TexturedOverdrawCostsMore) {
  Overdraw helmet{.triangles = 15'452, .depthPassed = 115'578, .shaded = 96'132, .texturesPerTriangle = 5.0};
  EXPECT_TRUE(zPrepassPays(helmet));
  helmet.texturesPerTriangle = 0.0;
  EXPECT_FALSE(zPrepassPays(helmet)) << "the same overdraw untextured";
}

TEST(ZPrepassRule, TheThresholdIsOverdrawnFragmentsPerTriangle) {
  const uint64_t triangles = 100'000, covered = 500'000;
  const auto at = uint64_t(kZPrepassFragmentsPerTriangle * double(triangles));
  EXPECT_FALSE(zPrepassPays({.triangles = triangles, .depthPassed = covered + at, .shaded = covered}));
  EXPECT_TRUE(zPrepassPays({.triangles = triangles, .depthPassed = covered + at + 1, .shaded = covered}));
  // The same overdraw over half the triangles pays.
  EXPECT_TRUE(zPrepassPays({.triangles = triangles / 2, .depthPassed = covered + at, .shaded = covered}));
}

TEST(ZPrepassRule, NoOverdrawNoPrepass) {
  EXPECT_FALSE(zPrepassPays({}));
  // Ties (coplanar surfaces) can pass forward-opaque's LESS_OR_EQUAL more often than the pre-pass's.
  const Overdraw ties{.triangles = 10, .depthPassed = 100, .shaded = 120};
  EXPECT_EQ(ties.overdrawn(), 0u);
  EXPECT_FALSE(zPrepassPays(ties));
  EXPECT_DOUBLE_EQ((Overdraw{.triangles = 1, .depthPassed = 300, .shaded = 100}).depthComplexity(), 3.0);
}

TEST(ZPrepassRule, AMeasurementGoesStaleWithSizeTrianglesOrCamera) {
  const glm::mat4 projection = glm::perspective(0.9f, 16.0f / 9.0f, 0.1f, 100.0f);
  const auto at = [&](glm::vec3 eye) { return projection * glm::lookAt(eye, glm::vec3(0.0f), {0.0f, 1.0f, 0.0f}); };
  const OverdrawView measured{1280, 720, 100'000, 0.0, at({0.0f, 1.0f, 5.0f})};
  EXPECT_FALSE(overdrawStale(measured, measured));
  OverdrawView v = measured;
  v.width = 640;
  EXPECT_TRUE(overdrawStale(measured, v));
  v = measured;
  v.triangles = 95'000;  // frustum culling dropped 5%
  EXPECT_FALSE(overdrawStale(measured, v));
  v.triangles = 80'000;
  EXPECT_TRUE(overdrawStale(measured, v));
  v = measured;
  v.viewProjection = at({0.01f, 1.0f, 5.0f});  // a small step
  EXPECT_FALSE(overdrawStale(measured, v));
  v.viewProjection = at({3.0f, 1.0f, 4.0f});  // around the model
  EXPECT_TRUE(overdrawStale(measured, v));
}

}  // namespace
}  // namespace sg::passes
