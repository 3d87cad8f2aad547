// Automatic charts: unique, gutters kept, triangles and attributes preserved.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/auto_chart.hpp>
#include <shadelgraph/shadel/chart_packing.hpp>
#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

#include "id_map_checks.hpp"
#include "shadel_test_support.hpp"

namespace sg::shadel {
namespace {

// Each chart's UV bounding box, from the output mesh itself.
std::vector<std::pair<glm::dvec2, glm::dvec2>> chartBoxes(const AutoChartResult& result) {
  std::vector<std::pair<glm::dvec2, glm::dvec2>> boxes(result.stats.charts, {glm::dvec2(INFINITY), glm::dvec2(-INFINITY)});
  uint32_t t = 0;
  for (const scene::Primitive& p : result.mesh.primitives)
    for (size_t i = 0; i < p.indices.size(); i += 3, ++t)
      for (size_t k = 0; k < 3; ++k) {
        auto& [lo, hi] = boxes[result.triangleChart[t]];
        lo = glm::min(lo, glm::dvec2(p.uv1[p.indices[i + k]]));
        hi = glm::max(hi, glm::dvec2(p.uv1[p.indices[i + k]]));
      }
  return boxes;
}

// Smallest gap, in texels at `resolution`, between any two charts' boxes (a
// lower bound on the distance between the charts).
double smallestGutterTexels(const AutoChartResult& result, uint32_t resolution) {
  const auto boxes = chartBoxes(result);
  double smallest = INFINITY;
  for (size_t a = 0; a < boxes.size(); ++a)
    for (size_t b = a + 1; b < boxes.size(); ++b) {
      const glm::dvec2 gap = glm::max(boxes[b].first - boxes[a].second, boxes[a].first - boxes[b].second);
      smallest = std::min(smallest, std::max(gap.x, gap.y) * resolution);
    }
  return smallest;
}

// The chart must be the mesh's shading chart, triangles and attributes kept.
void expectValidChart(const scene::Mesh& input, const AutoChartResult& result, const AutoChartOptions& options) {
  ASSERT_TRUE(result.ok()) << result.error;
  const scene::ChartVerdict verdict = scene::analyzeUvSet(result.mesh, 1);
  EXPECT_TRUE(verdict.unique) << verdict.reason;
  EXPECT_EQ(verdict.tileOffset, glm::vec2(0.0f));
  EXPECT_EQ(scene::chooseShadingChart(result.mesh).uvSet, 1);
  ASSERT_EQ(result.mesh.primitives.size(), input.primitives.size());
  for (size_t p = 0; p < input.primitives.size(); ++p) {
    const scene::Primitive& a = input.primitives[p];
    const scene::Primitive& b = result.mesh.primitives[p];
    ASSERT_EQ(a.indices.size(), b.indices.size());
    EXPECT_EQ(a.material, b.material);
    EXPECT_EQ(b.uv1.size(), b.positions.size());
    EXPECT_EQ(b.normals.size(), b.positions.size());
    EXPECT_EQ(b.uv0.empty(), a.uv0.empty());
    EXPECT_EQ(b.tangents.empty(), a.tangents.empty());
    for (size_t i = 0; i < a.indices.size(); ++i) {
      ASSERT_EQ(a.positions[a.indices[i]], b.positions[b.indices[i]]) << "corner " << i;
      ASSERT_EQ(a.normals[a.indices[i]], b.normals[b.indices[i]]);
      if (!a.uv0.empty()) {
        ASSERT_EQ(a.uv0[a.indices[i]], b.uv0[b.indices[i]]);
      }
    }
  }
  if (result.stats.charts > 1) {
    EXPECT_GE(smallestGutterTexels(result, options.resolution), options.gutterTexels * (1.0 - 1e-4));
  }
  EXPECT_GT(result.stats.utilisation, 0.0);
  EXPECT_LE(result.stats.utilisation, 1.0);
}

TEST(AutoChart, BoxGetsOneChartPerFace) {
  const scene::Primitive box = scene::makeBox(glm::vec3(1.0f, 2.0f, 3.0f));
  const AutoChartOptions options;
  scene::Mesh mesh;
  mesh.primitives.push_back(box);
  mesh.primitives[0].uv1.clear();
  const AutoChartResult result = autoChartMesh(mesh, options);
  expectValidChart(mesh, result, options);
  EXPECT_EQ(result.stats.charts, 6u);
  EXPECT_EQ(result.stats.overlapSplits, 0u);
  // Same density everywhere: each face's UV area is proportional to its world area.
  std::vector<double> uvArea(6, 0.0), worldArea(6, 0.0);
  const scene::Primitive& p = result.mesh.primitives[0];
  for (size_t i = 0, t = 0; i < p.indices.size(); i += 3, ++t) {
    const glm::dvec2 a(p.uv1[p.indices[i]]), b(p.uv1[p.indices[i + 1]]), c(p.uv1[p.indices[i + 2]]);
    uvArea[result.triangleChart[t]] += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    const glm::dvec3 pa(p.positions[p.indices[i]]), pb(p.positions[p.indices[i + 1]]), pc(p.positions[p.indices[i + 2]]);
    worldArea[result.triangleChart[t]] += 0.5 * glm::length(glm::cross(pb - pa, pc - pa));
  }
  for (size_t c = 0; c < 6; ++c) EXPECT_NEAR(uvArea[c] / worldArea[c], result.stats.scale * result.stats.scale, 1e-5);
}

TEST(AutoChart, SphereAndTorusAreUnique) {
  for (const scene::Primitive& shape : {scene::makeSphere(1.0f, 48, 24), scene::makeTorus(1.0f, 0.3f, 48, 24)}) {
    AutoChartOptions options;
    options.replaceUv1 = true;
    const AutoChartResult result = autoChartPrimitive(shape, options);
    scene::Mesh input;
    input.primitives.push_back(shape);
    expectValidChart(input, result, options);
    EXPECT_GT(result.stats.charts, 4u);
    EXPECT_GT(result.stats.verticesOut, result.stats.verticesIn) << "vertices split along chart borders";
  }
}

// A spiral ramp: every normal within a few degrees of +Z, so it grows as
// one chart, but two turns project onto each other.
TEST(AutoChart, SelfOverlappingProjectionIsCut) {
  scene::Primitive ramp;
  const int steps = 96;
  for (int i = 0; i <= steps; ++i) {
    const double angle = 4.0 * 3.14159265358979 * i / steps;  // two turns
    const double z = 0.05 * i / steps * 2.0;
    for (double r : {0.5, 1.0})
      ramp.positions.emplace_back(static_cast<float>(r * std::cos(angle)), static_cast<float>(r * std::sin(angle)),
                                  static_cast<float>(z));
  }
  for (uint32_t i = 0; i < static_cast<uint32_t>(steps); ++i) {
    const uint32_t a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
    ramp.indices.insert(ramp.indices.end(), {a, c, b, b, c, d});
  }
  ramp.normals.assign(ramp.positions.size(), glm::vec3(0, 0, 1));
  const AutoChartOptions options;
  const AutoChartResult result = autoChartPrimitive(ramp, options);
  scene::Mesh input;
  input.primitives.push_back(ramp);
  expectValidChart(input, result, options);
  EXPECT_GT(result.stats.overlapSplits, 0u);
  EXPECT_GE(result.stats.charts, 2u);
}

TEST(AutoChart, RefusesToOverwriteTexcoord1AndBadOptions) {
  scene::Mesh mesh;
  mesh.primitives.push_back(scene::makeBox(glm::vec3(1.0f)));
  mesh.primitives[0].uv1 = mesh.primitives[0].uv0;
  const AutoChartResult refused = autoChartMesh(mesh);
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(refused.error.find("TEXCOORD_1"), std::string::npos) << refused.error;
  EXPECT_EQ(refused.mesh.primitives[0].uv1, mesh.primitives[0].uv1) << "the input comes back unchanged";
  AutoChartOptions replace;
  replace.replaceUv1 = true;
  EXPECT_TRUE(autoChartMesh(mesh, replace).ok());
  AutoChartOptions badCone = replace;
  badCone.coneAngleDegrees = 95;
  EXPECT_FALSE(autoChartMesh(mesh, badCone).ok());
  // Gutters so wide that even empty cells do not fit.
  AutoChartOptions hugeGutter = replace;
  hugeGutter.resolution = 8;
  hugeGutter.gutterTexels = 4;
  EXPECT_FALSE(autoChartMesh(mesh, hugeGutter).ok());
}

TEST(ChartPacking, KeepsGuttersAndFillsReasonably) {
  std::vector<glm::dvec2> sizes;
  for (int i = 0; i < 200; ++i) sizes.emplace_back(1.0 + (i * 37 % 11), 1.0 + (i * 53 % 7));
  const double gutter = 4.0 / 1024;
  const ChartPacking packing = packCharts(sizes, gutter);
  ASSERT_TRUE(packing.fits);
  double used = 0.0;
  for (size_t a = 0; a < sizes.size(); ++a) {
    const glm::dvec2 lo = packing.origins[a], hi = lo + sizes[a] * packing.scale;
    EXPECT_GE(lo.x, gutter / 2 - 1e-12);
    EXPECT_GE(lo.y, gutter / 2 - 1e-12);
    EXPECT_LE(hi.x, 1.0 - gutter / 2 + 1e-12);
    EXPECT_LE(hi.y, 1.0 - gutter / 2 + 1e-12);
    used += sizes[a].x * sizes[a].y * packing.scale * packing.scale;
    for (size_t b = a + 1; b < sizes.size(); ++b) {
      const glm::dvec2 blo = packing.origins[b], bhi = blo + sizes[b] * packing.scale;
      const glm::dvec2 gap = glm::max(blo - hi, lo - bhi);
      EXPECT_GE(std::max(gap.x, gap.y), gutter - 1e-12) << a << " and " << b;
    }
  }
  EXPECT_GT(used, 0.6) << "shelf packing of these rectangles should fill well over half the square";
}

struct SampleCase {
  const char* model;
  uint32_t minCharts;
};

class AutoChartSamples : public ::testing::TestWithParam<SampleCase> {};

TEST_P(AutoChartSamples, ChartIsUniqueWithGuttersAndBakesAnIdMap) {
  SG_REQUIRE_ASSETS();
  scene::LoadOptions load;
  load.decodeImages = false;
  const scene::Scene scene = scene::loadGltf(test::samplePath(GetParam().model), load);
  for (const scene::Mesh& mesh : scene.meshes) {
    EXPECT_FALSE(scene::chooseShadingChart(mesh).unique) << "no usable chart of its own: why it needs one";
    const MeshTextureDensity texture = meshTextureDensity(scene, mesh);
    AutoChartOptions options;
    options.resolution = std::max(texture.resolution > 0 ? std::bit_ceil(texture.resolution) : 0u, 256u);
    auto start = std::chrono::steady_clock::now();
    const AutoChartResult result = autoChartMesh(mesh, options);
    const double chartSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expectValidChart(mesh, result, options);
    if (!result.ok()) continue;
    EXPECT_GE(result.stats.charts, GetParam().minCharts);

    const scene::ChartVerdict chart = scene::chooseShadingChart(result.mesh);
    IdMapOptions idOptions;
    idOptions.level0Size = chooseLevel0Size(result.mesh, chart, texture);
    start = std::chrono::steady_clock::now();
    const TriangleIdMap map = bakeTriangleIdMap(result.mesh, chart, idOptions);
    const double bakeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%-14s %6zu triangles: %4u charts (%u cut for overlap), utilisation %.1f%%, vertices %llu -> %llu, "
                "charted in %.3f s; ID map level 0 %u, %u levels, baked in %.3f s\n",
                GetParam().model, mesh.triangleCount(), result.stats.charts, result.stats.overlapSplits,
                100.0 * result.stats.utilisation, static_cast<unsigned long long>(result.stats.verticesIn),
                static_cast<unsigned long long>(result.stats.verticesOut), chartSeconds, map.levels.level0Size,
                map.levels.levelCount, bakeSeconds);
    const ChartTriangles triangles = chartTriangles(result.mesh, chart.uvSet, chart.tileOffset);
    for (uint32_t level = 0; level < map.levels.levelCount; ++level) {
      const test::LevelOwnership ownership = test::checkIdMapLevel(map, level, triangles, true);
      EXPECT_EQ(ownership.orphans, map.stats[level].orphanTriangles);
      if (level < 2) std::printf("    level %u: %u of %u triangles own a texel\n", level, ownership.owning, map.triangleCount);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Models, AutoChartSamples,
                         ::testing::Values(SampleCase{"Box", 6}, SampleCase{"BoxTextured", 6},
                                           SampleCase{"Duck", 20}, SampleCase{"DamagedHelmet", 50}),
                         [](const auto& param) { return std::string(param.param.model); });

}  // namespace
}  // namespace sg::shadel
