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

// The rectangle holds every pixel a point of the box projects to (row 0 at
// clip y = w, the renderer's flipped viewport), and stays near its extent.
TEST(Frustum, BoxScreenRectHoldsTheBox) {
  const glm::mat4 m = camera();
  const scene::Bounds box{{1.0f, 1.5f, -11.0f}, {3.0f, 2.5f, -9.0f}};
  const glm::ivec4 r = boxScreenRect(m, box, 800, 800);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec3 t(float(i % 10) / 9.0f, float((i / 10) % 10) / 9.0f, float(i / 100) / 9.0f);
    const glm::vec4 clip = m * glm::vec4(glm::mix(box.min, box.max, t), 1.0f);
    const float x = (clip.x / clip.w + 1.0f) * 400.0f, y = (1.0f - clip.y / clip.w) * 400.0f;
    EXPECT_TRUE(x >= float(r.x) && x <= float(r.z) && y >= float(r.y) && y <= float(r.w)) << x << "," << y;
  }
  EXPECT_GT(r.x, 400) << "right of centre: the right half";
  EXPECT_LT(r.w, 400) << "above the centre: rows from 0 down";
  EXPECT_LT(r.z - r.x, 140);  // 2 units at 9 to 11 away in a 90 degree view: about 90 of 800 pixels
  EXPECT_LT(r.w - r.y, 80);
}

TEST(Frustum, BoxScreenRectIsTheWholeOutputWhenBehindTheEye) {
  EXPECT_EQ(boxScreenRect(camera(), {{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}}, 640, 360), glm::ivec4(0, 0, 640, 360))
      << "the eye inside";
  EXPECT_EQ(boxScreenRect(camera(), {{-1.0f, -1.0f, 9.0f}, {1.0f, 1.0f, 11.0f}}, 640, 360), glm::ivec4(0, 0, 640, 360))
      << "behind";
  const glm::ivec4 off = boxScreenRect(camera(), {{29.0f, -1.0f, -11.0f}, {31.0f, 1.0f, -9.0f}}, 640, 360);
  EXPECT_TRUE(off.z <= off.x || off.w <= off.y) << "outside the view: empty after clamping";
  const glm::ivec4 none = boxScreenRect(camera(), scene::Bounds{}, 640, 360);
  EXPECT_TRUE(none.z <= none.x) << "an empty box covers nothing";
}

}  // namespace
}  // namespace sg::render
