// The screen term of level 0: one shadel per pixel where the view shows the mesh.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/shadel/level0_resolution.hpp>

namespace sg::shadel {
namespace {

// A unit quad in z = 0 over x, y in [0,1], its chart the [0,1]² square of TEXCOORD_0.
scene::Mesh unitQuad() {
  scene::Primitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.normals.assign(4, {0, 0, 1});
  p.uv0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
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

TEST(ScreenRateLevel0, OneShadelPerPixelUnderNearestRounding) {
  // 500 pixels per UV unit: 500 / sqrt(2) = 354 -> 512 (a level 0 of 256 would be
  // read magnified by log2(500/256) = 0.97 levels, past the nearest rounding).
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(0), glm::mat4(1.0f), fillView(), 500, 500), 512u);
  // 360 pixels: 255 -> 256 (256 is magnified by 0.49 levels: still read at level 0).
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(0), glm::mat4(1.0f), fillView(), 360, 360), 256u);
  // The object at half the size on screen needs half the shadels.
  const glm::mat4 half = glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f));
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(0), half, fillView(), 1000, 1000), 512u);
}

TEST(ScreenRateLevel0, DensestPartDecidesUpToTheCoverage) {
  // The same quad with its chart squeezed into the left half along u: twice the
  // pixels per UV unit along u, so sqrt(2) more per side.
  scene::Mesh mesh = unitQuad();
  for (glm::vec2& uv : mesh.primitives[0].uv0) uv.x *= 0.5f;
  EXPECT_EQ(screenRateLevel0Size(mesh, chartOf(0), glm::mat4(1.0f), fillView(), 362, 362), 512u);
  // A sliver with no UV area (1e-4 of the projected area) is below the 1% left out.
  scene::Primitive& p = mesh.primitives[0];
  p.positions.push_back({0.0f, 0.0f, 0.0f});
  p.positions.push_back({0.01f, 0.0f, 0.0f});
  p.positions.push_back({0.0f, 0.02f, 0.0f});
  p.uv0.insert(p.uv0.end(), 3, glm::vec2(0.25f));
  p.indices.insert(p.indices.end(), {4, 5, 6});
  EXPECT_EQ(screenRateLevel0Size(mesh, chartOf(0), glm::mat4(1.0f), fillView(), 362, 362), 512u);
  // With no coverage left out, it decides (and asks for more than any level 0 can have).
  EXPECT_GT(screenRateLevel0Size(mesh, chartOf(0), glm::mat4(1.0f), fillView(), 362, 362, 1.0), 1u << 20);
}

TEST(ScreenRateLevel0, NothingInViewAsksNothing) {
  const glm::mat4 aside = glm::translate(glm::mat4(1.0f), glm::vec3(3.0f, 0.0f, 0.0f));
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(0), aside, fillView(), 500, 500), 0u);
  // Behind a perspective camera at z = 2 looking down -z towards +z... i.e. the quad behind it.
  const glm::mat4 view = glm::lookAt(glm::vec3(0.5f, 0.5f, -2.0f), glm::vec3(0.5f, 0.5f, -3.0f), glm::vec3(0, 1, 0));
  const glm::mat4 projection = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(0), glm::mat4(1.0f), projection * view, 500, 500), 0u);
  // The same camera turned around sees it.
  const glm::mat4 facing = glm::lookAt(glm::vec3(0.5f, 0.5f, -2.0f), glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0, 1, 0));
  EXPECT_GT(screenRateLevel0Size(unitQuad(), chartOf(0), glm::mat4(1.0f), projection * facing, 500, 500), 0u);
  // No chart, no pixels: nothing.
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(-1), glm::mat4(1.0f), fillView(), 500, 500), 0u);
  EXPECT_EQ(screenRateLevel0Size(unitQuad(), chartOf(0), glm::mat4(1.0f), fillView(), 0, 0), 0u);
}

}  // namespace
}  // namespace sg::shadel
