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

}  // namespace
}  // namespace sg::render
