// Triangle-ID map baking on synthetic meshes.
#include <random>

#include <gtest/gtest.h>

#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

#include "id_map_checks.hpp"
#include "shadel_test_support.hpp"

namespace sg::shadel {
namespace {

using test::meshWithUvs;

scene::ChartVerdict uniqueChart(const scene::Mesh& mesh, const scene::UvChartOptions& options = {}) {
  scene::ChartVerdict verdict = scene::analyzeUvSet(mesh, 0, options);
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  return verdict;
}

IdMapOptions optionsFor(uint32_t level0, uint32_t dilation = 1) {
  IdMapOptions options;
  options.level0Size = level0;
  options.dilation = dilation;
  return options;
}

// [0,1]² as two triangles split along the diagonal from (0,0) to (1,1):
// triangle 0 is the upper right (v <= u), triangle 1 the lower left.
scene::Mesh unitQuad() { return meshWithUvs({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0, 1, 2, 0, 2, 3}); }

TEST(TriangleIdMap, TwoTriangleQuadHasExactIds) {
  const scene::Mesh mesh = unitQuad();
  for (uint32_t dilation : {0u, 1u}) {
    const TriangleIdMap map = bakeTriangleIdMap(mesh, uniqueChart(mesh), optionsFor(32, dilation));
    ASSERT_EQ(map.levels.levelCount, 3u);  // 32, 16, 8
    EXPECT_EQ(map.triangleCount, 2u);
    for (uint32_t level = 0; level < 3; ++level) {
      const uint32_t size = 32u >> level;
      for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x)
          // The diagonal's centres belong to the triangle it is a left edge of.
          ASSERT_EQ(map.at(level, x, y), y <= x ? 0u : 1u) << "level " << level << " (" << x << ", " << y << ")";
      const IdMapLevelStats& stats = map.stats[level];
      EXPECT_EQ(stats.size, size);
      EXPECT_EQ(stats.normalTexels, size * size);
      EXPECT_EQ(stats.conservativeTexels + stats.claimedTexels + stats.dilatedTexels + stats.emptyTexels, 0u);
      EXPECT_EQ(stats.owningTriangles, 2u);
      EXPECT_EQ(stats.orphanTriangles, 0u);
    }
  }
}

TEST(TriangleIdMap, ChartInAnotherTileIsShiftedAndTexelsOutsideStayEmpty) {
  // A quad over [0.25, 0.75]² of tile (2, 1).
  scene::Mesh mesh = meshWithUvs({{2.25f, 1.25f}, {2.75f, 1.25f}, {2.75f, 1.75f}, {2.25f, 1.75f}}, {0, 1, 2, 0, 2, 3});
  const scene::ChartVerdict chart = uniqueChart(mesh);
  ASSERT_EQ(chart.tileOffset, glm::vec2(2, 1));
  const TriangleIdMap plain = bakeTriangleIdMap(mesh, chart, optionsFor(16, 0));
  const TriangleIdMap dilated = bakeTriangleIdMap(mesh, chart, optionsFor(16, 1));
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      const bool inside = x >= 4 && x < 12 && y >= 4 && y < 12;
      const bool ring = x >= 3 && x < 13 && y >= 3 && y < 13;
      // Edges on texel borders touch no texel outside: the conservative pass adds nothing here.
      EXPECT_EQ(plain.at(0, x, y) != kNoTriangle, inside) << x << ", " << y;
      EXPECT_EQ(dilated.at(0, x, y) != kNoTriangle, ring) << x << ", " << y;
      if (inside) {
        EXPECT_EQ(plain.at(0, x, y), y <= x ? 0u : 1u);
      }
    }
  EXPECT_EQ(plain.stats[0].normalTexels, 64u);
  EXPECT_EQ(plain.stats[0].conservativeTexels, 0u);
  EXPECT_EQ(dilated.stats[0].dilatedTexels, 100u - 64u);
  // Dilated corners take the nearest triangle.
  EXPECT_EQ(dilated.at(0, 12, 3), 0u);
  EXPECT_EQ(dilated.at(0, 3, 12), 1u);
}

// Left half: a quad whose corner (0,0) holds a tiny triangle (1e-4 UV); right
// half: a quad with a sliver along its diagonal (1e-4 UV wide at one end).
scene::Mesh tinyAndSliver() {
  const float e = 1e-4f;
  return meshWithUvs(
      {// tiny corner: A, E (on AB), F (on AD), B, C, D
       {0, 0}, {e, 0}, {0, e}, {0.5f, 0}, {0.5f, 1}, {0, 1},
       // sliver quad: A', B', C', D', G (next to C', toward D')
       {0.5f, 0}, {1, 0}, {1, 1}, {0.5f, 1}, {1 - e, 1}},
      {0, 1, 2,            // 0: tiny
       4, 5, 2, 4, 2, 1, 4, 1, 3,  // 1-3: the rest of the left quad, fanned from C
       6, 7, 8,            // 4: right quad, upper right of its diagonal
       6, 8, 10,           // 5: the sliver
       6, 10, 9});         // 6: the rest
}

TEST(TriangleIdMap, TinyAndSliverTrianglesOwnATexelAtEveryLevel) {
  const scene::Mesh mesh = tinyAndSliver();
  const scene::ChartVerdict chart = uniqueChart(mesh);
  const TriangleIdMap map = bakeTriangleIdMap(mesh, chart, optionsFor(256));
  const ChartTriangles triangles = chartTriangles(mesh, 0, glm::vec2(0.0f));
  ASSERT_EQ(map.levels.levelCount, 6u);  // 256 .. 8
  uint64_t claimed = 0;
  for (uint32_t level = 0; level < map.levels.levelCount; ++level) {
    const test::LevelOwnership ownership = test::checkIdMapLevel(map, level, triangles, true);
    EXPECT_EQ(ownership.orphans, 0u) << "level " << level;
    EXPECT_EQ(map.stats[level].orphanTriangles, 0u);
    EXPECT_EQ(map.stats[level].owningTriangles, 7u);
    for (uint32_t t : {0u, 5u}) {
      const auto ids = map.level(level);
      EXPECT_GE(std::count(ids.begin(), ids.end(), t), 1) << "triangle " << t << " at level " << level;
    }
    claimed += map.stats[level].claimedTexels;
  }
  EXPECT_GT(claimed, 0u) << "the tiny triangle only gets a texel by claiming it";
  // Without claims the tiny triangle is an orphan.
  IdMapOptions noClaims = optionsFor(256);
  noClaims.claimOrphans = false;
  EXPECT_GT(bakeTriangleIdMap(mesh, chart, noClaims).stats[0].orphanTriangles, 0u);
}

TEST(TriangleIdMap, ZeroAreaTrianglesOwnNothingAndAreCovered) {
  scene::Mesh mesh = unitQuad();
  scene::Primitive& p = mesh.primitives[0];
  // A triangle with collinear UVs inside the quad (it has area in 3D, none in UV).
  for (glm::vec2 uv : {glm::vec2(0.1f, 0.3f), glm::vec2(0.2f, 0.3f), glm::vec2(0.3f, 0.3f)}) {
    p.uv0.push_back(uv);
    p.positions.emplace_back(uv, 1.0f);
    p.normals.emplace_back(0, 0, 1);
  }
  p.indices.insert(p.indices.end(), {4, 5, 6});
  scene::UvChartOptions lenient;  // one in three is more zero-area triangles than a real chart may have
  lenient.maxZeroAreaFraction = 0.5;
  const TriangleIdMap map = bakeTriangleIdMap(mesh, uniqueChart(mesh, lenient), optionsFor(64));
  EXPECT_EQ(map.triangleCount, 3u);
  EXPECT_EQ(map.zeroAreaTriangles, 1u);
  for (uint32_t level = 0; level < map.levels.levelCount; ++level) {
    const auto ids = map.level(level);
    EXPECT_EQ(std::count(ids.begin(), ids.end(), 2u), 0) << "a zero-area triangle owns nothing";
    EXPECT_EQ(map.stats[level].zeroAreaUncovered, 0u) << "its UVs lie on texels of other triangles";
    EXPECT_EQ(map.stats[level].orphanTriangles, 0u) << "zero-area triangles are not orphans";
  }
}

TEST(TriangleIdMap, OrphansOnlyWhereTexelsRunOut) {
  // 16 x 16 quads = 512 triangles over an 8x8 level: at most 64 can own a
  // texel, and the claims reach that maximum.
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> indices;
  const int n = 16;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) uvs.emplace_back(static_cast<float>(x) / n, static_cast<float>(y) / n);
  const auto at = [n](int x, int y) { return static_cast<uint32_t>(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) indices.insert(indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y), at(x + 1, y + 1), at(x, y + 1)});
  const scene::Mesh mesh = meshWithUvs(uvs, indices);
  const TriangleIdMap map = bakeTriangleIdMap(mesh, uniqueChart(mesh), optionsFor(32));
  const ChartTriangles triangles = chartTriangles(mesh, 0, glm::vec2(0.0f));
  ASSERT_EQ(map.levels.levelCount, 3u);  // 32, 16, 8
  const uint32_t expectedOwners[3] = {512, 256, 64};
  for (uint32_t level = 0; level < 3; ++level) {
    const test::LevelOwnership ownership = test::checkIdMapLevel(map, level, triangles, true);
    EXPECT_EQ(ownership.owning, expectedOwners[level]) << "level " << level;
    EXPECT_EQ(map.stats[level].owningTriangles, expectedOwners[level]);
    EXPECT_EQ(map.stats[level].orphanTriangles, 512 - expectedOwners[level]);
  }
}

TEST(TriangleIdMap, RandomMeshesHaveNoHolesAndOnlyPigeonholedOrphans) {
  std::mt19937 rng(11);
  for (int round = 0; round < 4; ++round) {
    // A jittered grid over part of the chart, so it has borders inside the map.
    const int n = 6 + round * 5;
    std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) {
        glm::vec2 p(static_cast<float>(x), static_cast<float>(y));
        if (x > 0 && x < n && y > 0 && y < n) p += glm::vec2(jitter(rng), jitter(rng));
        uvs.push_back(glm::vec2(0.13f) + p / static_cast<float>(n) * 0.71f);
      }
    const auto at = [n](int x, int y) { return static_cast<uint32_t>(y * (n + 1) + x); };
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        indices.insert(indices.end(), {at(x, y), at(x + 1, y), at(x, y + 1), at(x + 1, y), at(x + 1, y + 1), at(x, y + 1)});
    const scene::Mesh mesh = meshWithUvs(uvs, indices);
    const TriangleIdMap map = bakeTriangleIdMap(mesh, uniqueChart(mesh), optionsFor(64));
    const ChartTriangles triangles = chartTriangles(mesh, 0, glm::vec2(0.0f));
    for (uint32_t level = 0; level < map.levels.levelCount; ++level) {
      const test::LevelOwnership ownership = test::checkIdMapLevel(map, level, triangles, true);
      EXPECT_EQ(ownership.orphans, map.stats[level].orphanTriangles) << "round " << round << " level " << level;
      EXPECT_EQ(ownership.owning, map.stats[level].owningTriangles);
    }
  }
}

TEST(TriangleIdMap, RejectsMeshesWithoutTheChartsUvSet) {
  const scene::Mesh mesh = unitQuad();
  scene::ChartVerdict noSet;
  EXPECT_THROW(bakeTriangleIdMap(mesh, noSet, optionsFor(16)), std::invalid_argument);
  scene::ChartVerdict second = uniqueChart(mesh);
  second.uvSet = 1;
  EXPECT_THROW(bakeTriangleIdMap(mesh, second, optionsFor(16)), std::invalid_argument);
  EXPECT_THROW(bakeTriangleIdMap(mesh, uniqueChart(mesh), optionsFor(100)), std::invalid_argument);
}

}  // namespace
}  // namespace sg::shadel
