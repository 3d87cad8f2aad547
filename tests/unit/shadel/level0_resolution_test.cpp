// The screen term of level 0: one shadel per pixel on the narrow triangles the view shows.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/shadel/level0_resolution.hpp>

namespace sg::shadel {
namespace {

// A quad in z = 0 over x in [0,1], y in [0,h], its chart the same square of TEXCOORD_0 (u = x, v = y).
scene::Mesh quad(float h) {
  scene::Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, h, 0}, {0, h, 0}};
  p.normals.assign(4, {0, 0, 1});
  p.uv0 = {{0, 0}, {1, 0}, {1, h}, {0, h}};
  p.indices = {0, 1, 2, 0, 2, 3};
  scene::Mesh mesh;
  mesh.primitives.push_back(p);
  return mesh;
}

scene::ChartVerdict chartOf(int uvSet) {
  scene::ChartVerdict chart;
  chart.uvSet = uvSet;
  chart.unique = true;
  return chart;
}

// Orthographic: world x, y in [0,1] fill a width x height view.
glm::mat4 fillView() { return glm::ortho(0.0f, 1.0f, 0.0f, 1.0f, -1.0f, 1.0f); }

const glm::mat4 kIdentity(1.0f);

TEST(ScreenRateLevel0, WideTrianglesAskNothing) {
  // The unit square's triangles are 45 shadels high at level 0 = 64: shading
  // magnified there is only magnified, as its texture would be.
  EXPECT_EQ(screenRateLevel0Size(quad(1.0f), chartOf(0), kIdentity, fillView(), 500, 500, 64), 0u);
}

TEST(ScreenRateLevel0, NarrowTrianglesAskOneShadelPerPixelUnderNearestRounding) {
  // A strip 0.02 high: 1.3 shadels at level 0 = 64, so narrow.
  // 500 pixels per UV unit: 500 / sqrt(2) = 354 -> 512 (a level 0 of 256 would be
  // read magnified by log2(500/256) = 0.97 levels, past the nearest rounding).
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), kIdentity, fillView(), 500, 500, 64), 512u);
  // 360 pixels: 255 -> 256 (256 is magnified by 0.49 levels: still read at level 0).
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), kIdentity, fillView(), 360, 360, 64), 256u);
  // The object at half the size on screen needs half the shadels.
  const glm::mat4 half = glm::scale(kIdentity, glm::vec3(0.5f, 0.5f, 1.0f));
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), half, fillView(), 1000, 1000, 64), 512u);
  // At level 0 = 256 the strip is 5 shadels high: no longer narrow.
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), kIdentity, fillView(), 500, 500, 256), 0u);
}

TEST(ScreenRateLevel0, SliversBelowTheCoverageAreLeftOut) {
  scene::Mesh mesh = quad(0.02f);
  // A sliver with no UV area, 1% of the strip's projected area: left out.
  scene::Primitive& p = mesh.primitives[0];
  p.positions.push_back({0.0f, 0.0f, 0.0f});
  p.positions.push_back({0.02f, 0.0f, 0.0f});
  p.positions.push_back({0.0f, 0.0199f, 0.0f});
  p.uv0.insert(p.uv0.end(), 3, glm::vec2(0.25f));
  p.indices.insert(p.indices.end(), {4, 5, 6});
  EXPECT_EQ(screenRateLevel0Size(mesh, chartOf(0), kIdentity, fillView(), 500, 500, 64), 512u);
  // With no coverage left out, it decides (and asks for more than any level 0 can have).
  EXPECT_GT(screenRateLevel0Size(mesh, chartOf(0), kIdentity, fillView(), 500, 500, 64, 4.0, 1.0), 1u << 20);
}

TEST(ScreenRateLevel0, NothingInViewAsksNothing) {
  const glm::mat4 aside = glm::translate(kIdentity, glm::vec3(3.0f, 0.0f, 0.0f));
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), aside, fillView(), 500, 500, 64), 0u);
  // A perspective camera at z = -2 looking away from the strip (towards -z)...
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  const glm::mat4 away = glm::lookAt(glm::vec3(0.5f, 0.0f, -2.0f), glm::vec3(0.5f, 0.0f, -3.0f), glm::vec3(0, 1, 0));
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), kIdentity, projection * away, 500, 500, 64), 0u);
  // ...and turned towards it.
  const glm::mat4 facing = glm::lookAt(glm::vec3(0.5f, 0.0f, -2.0f), glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0, 1, 0));
  EXPECT_GT(screenRateLevel0Size(quad(0.02f), chartOf(0), kIdentity, projection * facing, 500, 500, 64), 0u);
  // No chart, no pixels: nothing.
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(-1), kIdentity, fillView(), 500, 500, 64), 0u);
  EXPECT_EQ(screenRateLevel0Size(quad(0.02f), chartOf(0), kIdentity, fillView(), 0, 0, 64), 0u);
}

}  // namespace
}  // namespace sg::shadel
