// Shading-UV chart analysis.
#include <gtest/gtest.h>

#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/uv_chart.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

// A primitive whose UV set 0 is exactly `uvs`, laid flat in 3D (z = 0).
Primitive withUvs(std::vector<glm::vec2> uvs, std::vector<uint32_t> indices) {
  Primitive p;
  for (const glm::vec2 uv : uvs) p.positions.emplace_back(uv, 0.0f);
  p.normals.assign(uvs.size(), glm::vec3(0, 0, 1));
  p.uv0 = std::move(uvs);
  p.indices = std::move(indices);
  return p;
}

// An n x n grid of quads covering [origin, origin + size]², two triangles each.
Primitive grid(int n, glm::vec2 origin = glm::vec2(0.0f), float size = 1.0f) {
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> indices;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) uvs.push_back(origin + glm::vec2(x, y) * size / static_cast<float>(n));
  const auto at = [n](int x, int y) { return static_cast<uint32_t>(y * (n + 1) + x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) indices.insert(indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1), at(x, y), at(x + 1, y + 1), at(x, y + 1)});
  return withUvs(std::move(uvs), std::move(indices));
}

TEST(UvChart, GridIsUnique) {
  const ChartVerdict verdict = analyzeUvSet(grid(20), 0);
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.uvSet, 0);
  EXPECT_EQ(verdict.triangles, 800u);
  EXPECT_EQ(verdict.overlappingPairs, 0u) << "shared edges and vertices are not overlaps";
  EXPECT_EQ(verdict.outOfRangeUvs, 0u);
  EXPECT_EQ(verdict.zeroAreaTriangles, 0u);
  EXPECT_EQ(verdict.tileOffset, glm::vec2(0.0f));
}

TEST(UvChart, IdenticalTrianglesOverlap) {
  const ChartVerdict verdict = analyzeUvSet(withUvs({{0, 0}, {1, 0}, {0, 1}}, {0, 1, 2, 0, 2, 1}), 0);
  EXPECT_FALSE(verdict.unique);
  EXPECT_EQ(verdict.overlappingPairs, 1u);
  EXPECT_EQ(verdict.overlappingTriangles, 2u);
  EXPECT_NE(verdict.reason.find("1 overlapping triangle pairs"), std::string::npos) << verdict.reason;
}

TEST(UvChart, PartialOverlapAndMereTouching) {
  // Second triangle shifted by half: interiors intersect.
  const ChartVerdict overlap =
      analyzeUvSet(withUvs({{0, 0}, {0.5f, 0}, {0, 0.5f}, {0.2f, 0.1f}, {0.7f, 0.1f}, {0.2f, 0.6f}}, {0, 1, 2, 3, 4, 5}), 0);
  EXPECT_EQ(overlap.overlappingPairs, 1u);
  // Touching at one vertex only.
  const ChartVerdict touching =
      analyzeUvSet(withUvs({{0, 0}, {0.5f, 0}, {0, 0.5f}, {0.5f, 0}, {1, 0}, {1, 0.5f}}, {0, 1, 2, 3, 4, 5}), 0);
  EXPECT_EQ(touching.overlappingPairs, 0u);
  // One triangle inside another (no edge crosses: the separating-axis test must still catch it).
  const ChartVerdict nested =
      analyzeUvSet(withUvs({{0, 0}, {1, 0}, {0, 1}, {0.1f, 0.1f}, {0.2f, 0.1f}, {0.1f, 0.2f}}, {0, 1, 2, 3, 4, 5}), 0);
  EXPECT_EQ(nested.overlappingPairs, 1u);
}

TEST(UvChart, TinyOverlapBelowThresholdIsIgnored) {
  // Two triangles that share an edge, the second nudged across it by 1e-7:
  // an overlap of ~1e-8 in area, below overlapAreaEpsilon... only if the
  // epsilon is raised, which shows the threshold is what decides.
  const Primitive p = withUvs({{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 1}, {-1e-7f, 1}}, {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(analyzeUvSet(p, 0).overlappingPairs, 1u);
  UvChartOptions lenient;
  lenient.overlapAreaEpsilon = 1e-6;
  EXPECT_EQ(analyzeUvSet(p, 0, lenient).overlappingPairs, 0u);
}

TEST(UvChart, OutOfRangeUvs) {
  Primitive p = grid(4);
  p.uv0[0] = glm::vec2(-0.5f, 0.0f);
  const ChartVerdict verdict = analyzeUvSet(p, 0);
  EXPECT_FALSE(verdict.unique);
  EXPECT_EQ(verdict.outOfRangeUvs, 1u);
  EXPECT_NE(verdict.reason.find("outside one unit tile"), std::string::npos) << verdict.reason;
  // Within rangeEpsilon is fine.
  p.uv0[0] = glm::vec2(-0.00005f, 0.0f);
  EXPECT_EQ(analyzeUvSet(p, 0).outOfRangeUvs, 0u);
}

TEST(UvChart, ChartInAnotherTileIsShifted) {
  const ChartVerdict verdict = analyzeUvSet(grid(8, glm::vec2(2.0f, 1.0f)), 0);
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.tileOffset, glm::vec2(2.0f, 1.0f));
}

TEST(UvChart, ZeroAreaTriangles) {
  Primitive p = grid(10);  // 200 triangles
  // Add one degenerate triangle (three collinear UVs) on the chart's edge, of non-zero surface area.
  const auto base = static_cast<uint32_t>(p.uv0.size());
  for (glm::vec2 uv : {glm::vec2(0, 0), glm::vec2(0.5f, 0), glm::vec2(1, 0)}) {
    p.uv0.push_back(uv);
    p.positions.emplace_back(uv.x, uv.y, uv.x * uv.x);  // on a parabola: not collinear
    p.normals.emplace_back(0, 0, 1);
  }
  p.indices.insert(p.indices.end(), {base, base + 1, base + 2});
  const ChartVerdict verdict = analyzeUvSet(p, 0);
  EXPECT_EQ(verdict.zeroAreaTriangles, 1u);
  EXPECT_TRUE(verdict.unique) << "a few zero-area triangles are tolerated: " << verdict.reason;
  // A set of all zeros is no chart.
  Primitive zeros = grid(4);
  for (glm::vec2& uv : zeros.uv0) uv = glm::vec2(0.25f);
  const ChartVerdict degenerate = analyzeUvSet(zeros, 0);
  EXPECT_FALSE(degenerate.unique);
  EXPECT_EQ(degenerate.zeroAreaTriangles, degenerate.triangles);
}

TEST(UvChart, TrianglesOfZeroSurfaceAreaAreIgnored) {
  // A CAD-style mesh: more than 1% of its triangles are degenerate in 3D
  // (two coincident corners) and in UV, and one stacks over the chart.
  Primitive p = grid(10);  // 200 triangles
  const auto base = static_cast<uint32_t>(p.uv0.size());
  for (int t = 0; t < 5; ++t) {
    const glm::vec2 uv(0.1f * float(t) + 0.05f, 0.5f);
    for (glm::vec2 corner : {uv, uv, uv + glm::vec2(0.02f, 0.0f)}) {
      p.uv0.push_back(corner);
      p.positions.emplace_back(corner, 0.0f);
      p.normals.emplace_back(0, 0, 1);
    }
  }
  // Collinear in 3D but with UV area: it overlaps the grid's triangles.
  for (glm::vec2 uv : {glm::vec2(0.2f, 0.2f), glm::vec2(0.6f, 0.2f), glm::vec2(0.4f, 0.6f)}) {
    p.uv0.push_back(uv);
    p.positions.emplace_back(uv.x, 0.0f, 0.0f);
    p.normals.emplace_back(0, 0, 1);
  }
  for (uint32_t v = 0; v < 18; ++v) p.indices.push_back(base + v);
  const ChartVerdict verdict = analyzeUvSet(p, 0);
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.degenerateTriangles, 6u);
  EXPECT_EQ(verdict.triangles, 200u);
  EXPECT_EQ(verdict.zeroAreaTriangles, 0u);
  EXPECT_EQ(verdict.overlappingPairs, 0u);
  // Skinned, the same triangles may open up when posed: they count.
  p.joints0.assign(p.positions.size(), glm::uvec4(0));
  p.weights0.assign(p.positions.size(), glm::vec4(1, 0, 0, 0));
  const ChartVerdict skinned = analyzeUvSet(p, 0);
  EXPECT_FALSE(skinned.unique);
  EXPECT_EQ(skinned.degenerateTriangles, 0u);
  EXPECT_EQ(skinned.zeroAreaTriangles, 5u);
  EXPECT_GT(skinned.overlappingPairs, 0u);
}

TEST(UvChart, PrefersTexcoord1) {
  Primitive p = grid(4);
  p.uv1 = p.uv0;
  std::swap(p.uv0[0], p.uv0[6]);  // fold set 0
  ChartVerdict verdict = chooseShadingChart(p);
  EXPECT_EQ(verdict.uvSet, 1);
  EXPECT_TRUE(verdict.unique);
  // Set 1 broken, set 0 fine: falls back, and says why.
  std::swap(p.uv0, p.uv1);
  verdict = chooseShadingChart(p);
  EXPECT_EQ(verdict.uvSet, 0);
  EXPECT_TRUE(verdict.unique);
  EXPECT_NE(verdict.reason.find("TEXCOORD_1: "), std::string::npos) << verdict.reason;
}

TEST(UvChart, MeshPrimitivesShareOneChart) {
  Mesh mesh;
  mesh.primitives = {grid(4), grid(2, glm::vec2(0.25f), 0.5f)};
  EXPECT_TRUE(chooseShadingChart(mesh.primitives[0]).unique);
  EXPECT_TRUE(chooseShadingChart(mesh.primitives[1]).unique);
  const ChartVerdict together = chooseShadingChart(mesh);
  EXPECT_FALSE(together.unique) << "each primitive alone is fine, together they overlap";
  EXPECT_GT(together.overlappingPairs, 0u);
}

TEST(UvChart, ManyTrianglesStayFast) {
  // 180,000 triangles: quadratic pair testing would take minutes, the grid a blink.
  const ChartVerdict verdict = analyzeUvSet(grid(300), 0);
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.triangles, 180'000u);
}

TEST(UvChart, OverlapCountingStopsAtTheLimit) {
  Primitive p = withUvs({{0, 0}, {1, 0}, {0, 1}}, {});
  for (int i = 0; i < 100; ++i) p.indices.insert(p.indices.end(), {0, 1, 2});  // 4950 overlapping pairs
  UvChartOptions options;
  options.maxOverlappingPairs = 10;
  const ChartVerdict verdict = analyzeUvSet(p, 0, options);
  EXPECT_TRUE(verdict.countsTruncated);
  EXPECT_EQ(verdict.overlappingPairs, 10u);
  EXPECT_FALSE(verdict.unique);
}

TEST(UvChart, NoUvs) {
  Primitive p = grid(2);
  p.uv0.clear();
  const ChartVerdict verdict = chooseShadingChart(p);
  EXPECT_EQ(verdict.uvSet, -1);
  EXPECT_FALSE(verdict.unique);
}

// The sample models. Surprise: DamagedHelmet's TEXCOORD_0 is NOT a unique
// chart, whatever shared/assets/README.md says: its left and right halves are
// mirrored onto the same UVs (6,942 pairs of triangles with identical UV
// triangles). It does sit in tile (0, 1) and has 10 zero-area triangles.
TEST(UvChartAssets, DamagedHelmetIsMirrored) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("DamagedHelmet"), LoadOptions{.decodeImages = false});
  const ChartVerdict verdict = chooseShadingChart(scene.meshes.at(0).primitives.at(0));
  EXPECT_EQ(verdict.uvSet, 0);
  EXPECT_FALSE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.triangles, 15'452u);
  EXPECT_EQ(verdict.zeroAreaTriangles, 10u);
  EXPECT_EQ(verdict.outOfRangeUvs, 0u);
  EXPECT_EQ(verdict.tileOffset, glm::vec2(0.0f, 1.0f));
  EXPECT_GE(verdict.overlappingPairs, 6'942u) << "at least the identical mirrored pairs";
  EXPECT_GT(verdict.overlappingTriangles, 13'884u);
}

TEST(UvChartAssets, SuzanneIsUnique) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("Suzanne"), LoadOptions{.decodeImages = false});
  const ChartVerdict verdict = chooseShadingChart(scene.meshes.at(0));
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.uvSet, 0);
  EXPECT_EQ(verdict.zeroAreaTriangles, 0u);
}

// Also contrary to the assets README: the Duck's halves are mirrored too
// (UV area adds up to 1.2 of the tile, half the triangles flipped).
TEST(UvChartAssets, DuckIsMirrored) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("Duck"), LoadOptions{.decodeImages = false});
  const ChartVerdict verdict = chooseShadingChart(scene.meshes.at(0));
  EXPECT_EQ(verdict.uvSet, 0);
  EXPECT_FALSE(verdict.unique) << verdict.reason;
  EXPECT_GT(verdict.overlappingTriangles, verdict.triangles / 2);
}

TEST(UvChartAssets, NormalTangentMirrorTestIsNotUnique) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("NormalTangentMirrorTest"), LoadOptions{.decodeImages = false});
  const ChartVerdict verdict = chooseShadingChart(scene.meshes.at(0));
  EXPECT_EQ(verdict.uvSet, 0);
  EXPECT_FALSE(verdict.unique);
  EXPECT_GT(verdict.overlappingPairs, 0u);
}

TEST(UvChartAssets, BoxHasNoUvs) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("Box"));
  const ChartVerdict verdict = chooseShadingChart(scene.meshes.at(0));
  EXPECT_EQ(verdict.uvSet, -1);
  EXPECT_FALSE(verdict.unique);
  EXPECT_NE(verdict.reason.find("no TEXCOORD_0 or TEXCOORD_1"), std::string::npos);
}

// MultiUVTest's TEXCOORD_1 maps every cube face onto the same square (40
// overlapping pairs), its TEXCOORD_0 is a proper unwrap: set 0 is chosen.
TEST(UvChartAssets, MultiUvTestFallsBackToTexcoord0) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("MultiUVTest"), LoadOptions{.decodeImages = false});
  const Mesh& mesh = scene.meshes.at(0);
  const ChartVerdict second = analyzeUvSet(mesh, 1);
  EXPECT_FALSE(second.unique);
  EXPECT_EQ(second.overlappingPairs, 40u);
  const ChartVerdict chosen = chooseShadingChart(mesh);
  EXPECT_EQ(chosen.uvSet, 0);
  EXPECT_TRUE(chosen.unique) << chosen.reason;
}

}  // namespace
}  // namespace sg::scene
