#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/render/frustum.hpp>

namespace sg::render {
namespace {

// A camera at the origin looking down -Z, Vulkan depth range.
glm::mat4 camera() {
  glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
  return projection * glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST(Frustum, InsideOutsideAndStraddling) {
  EXPECT_TRUE(sphereInFrustum(camera(), {0.0f, 0.0f, -10.0f, 1.0f}));
  EXPECT_FALSE(sphereInFrustum(camera(), {0.0f, 0.0f, 10.0f, 1.0f})) << "behind";
  EXPECT_FALSE(sphereInFrustum(camera(), {30.0f, 0.0f, -10.0f, 1.0f})) << "far right of a 90 degree view";
  EXPECT_TRUE(sphereInFrustum(camera(), {10.5f, 0.0f, -10.0f, 1.0f})) << "straddles the right plane";
  EXPECT_FALSE(sphereInFrustum(camera(), {0.0f, 0.0f, -200.0f, 1.0f})) << "beyond the far plane";
  EXPECT_TRUE(sphereInFrustum(camera(), {0.0f, 0.0f, 0.5f, 1.0f})) << "around the eye";
}

TEST(Frustum, SphereBeyondNearPlane) {
  EXPECT_TRUE(sphereBeyondNearPlane(camera(), {0.0f, 0.0f, -10.0f, 1.0f}));
  EXPECT_TRUE(sphereBeyondNearPlane(camera(), {0.0f, 0.0f, -1.2f, 1.0f})) << "its nearest point 0.2 away, near 0.1";
  EXPECT_FALSE(sphereBeyondNearPlane(camera(), {0.0f, 0.0f, -1.05f, 1.0f})) << "the near plane cuts it";
  EXPECT_FALSE(sphereBeyondNearPlane(camera(), {0.0f, 0.0f, -0.5f, 1.0f})) << "the eye is inside";
  EXPECT_FALSE(sphereBeyondNearPlane(camera(), {0.0f, 0.0f, 10.0f, 1.0f})) << "behind";
  EXPECT_TRUE(sphereBeyondNearPlane(camera(), {30.0f, 0.0f, -10.0f, 1.0f})) << "outside the view, still beyond";
  const glm::mat4 ortho = glm::orthoRH_ZO(-5.0f, 5.0f, -5.0f, 5.0f, 1.0f, 50.0f);
  EXPECT_TRUE(sphereBeyondNearPlane(ortho, {0.0f, 0.0f, -3.0f, 1.5f}));
  EXPECT_FALSE(sphereBeyondNearPlane(ortho, {0.0f, 0.0f, -2.0f, 1.5f})) << "orthographic near plane at 1 cuts it";
}

}  // namespace
}  // namespace sg::render
