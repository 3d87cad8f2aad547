// Which objects a moved shadow caster may darken (render::shadowMayFallOn):
// the decoupled path reshades exactly those instead of reusing their stored
// shadow term (DecoupledShading::markShadowChanges). No device.
#include <gtest/gtest.h>

#include <shadelgraph/render/shadow_views.hpp>

namespace sg::test {
namespace {

const glm::vec4 kCaster{0.0f, 2.0f, 0.0f, 0.5f};  // a ball 2 units up

TEST(ShadowMayFallOn, ADirectionalLightsShadowRunsAlongItsDirectionOnly) {
  const scene::Light sun{.type = scene::LightType::Directional, .direction = {0.0f, -1.0f, 0.0f}};
  EXPECT_TRUE(render::shadowMayFallOn(sun, kCaster, {0.0f, 0.0f, 0.0f, 1.0f})) << "the ground under it";
  EXPECT_TRUE(render::shadowMayFallOn(sun, kCaster, {0.0f, -50.0f, 0.0f, 0.1f})) << "far down the cylinder";
  EXPECT_FALSE(render::shadowMayFallOn(sun, kCaster, {3.0f, 0.0f, 0.0f, 1.0f})) << "beside the cylinder";
  EXPECT_FALSE(render::shadowMayFallOn(sun, kCaster, {0.0f, 5.0f, 0.0f, 1.0f})) << "between the sun and the caster";
}

TEST(ShadowMayFallOn, APointLightsShadowIsTheConeBehindTheCaster) {
  const scene::Light bulb{.type = scene::LightType::Point, .position = {0.0f, 4.0f, 0.0f}};
  EXPECT_TRUE(render::shadowMayFallOn(bulb, kCaster, {0.0f, 0.0f, 0.0f, 0.5f})) << "straight behind";
  // The cone widens (half angle asin(0.5 / 2), 14.5°): at the ground it reaches about 1 unit out.
  EXPECT_TRUE(render::shadowMayFallOn(bulb, kCaster, {0.9f, 0.0f, 0.0f, 0.1f})) << "inside the widened cone";
  EXPECT_FALSE(render::shadowMayFallOn(bulb, kCaster, {3.0f, 0.0f, 0.0f, 0.5f})) << "outside the cone";
  EXPECT_FALSE(render::shadowMayFallOn(bulb, kCaster, {0.0f, 3.4f, 0.0f, 0.2f})) << "nearer the light than the caster";
  EXPECT_TRUE(render::shadowMayFallOn(bulb, {0.0f, 4.0f, 0.0f, 1.0f}, {5.0f, 0.0f, 0.0f, 0.5f}))
      << "a caster around the light may shadow anything";
}

}  // namespace
}  // namespace sg::test
