// How evenly a unique chart spreads shadels over the surface: what sends
// Suzanne's TEXCOORD_0 to an automatic chart (or forward in auto mode).
#include <cmath>

#include <gtest/gtest.h>

#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/chart_density.hpp>

#include "test_support.hpp"

namespace sg::shadel {
namespace {

// Unit squares side by side along x in world space (quad i spans x in [i, i+1]),
// each mapped to a UV square of side uvSides[i] (placed apart along u).
scene::Mesh quads(std::initializer_list<float> uvSides) {
  scene::Mesh mesh;
  scene::Primitive& p = mesh.primitives.emplace_back();
  float x = 0.0f, u = 0.0f;
  for (float side : uvSides) {
    const auto base = static_cast<uint32_t>(p.positions.size());
    for (glm::vec2 corner : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
      p.positions.emplace_back(x + corner.x, corner.y, 0.0f);
      p.uv0.push_back(glm::vec2(u, 0.0f) + corner * side);
    }
    p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    x += 1.0f;
    u += side + 0.01f;
  }
  return mesh;
}

TEST(ChartDensity, UniformChartIsEven) {
  const ChartDensity d = chartDensity(quads({0.1f, 0.1f, 0.1f, 0.1f}), 0);
  EXPECT_NEAR(d.worldArea, 4.0, 1e-9);
  EXPECT_NEAR(d.meanDensity, 0.01, 1e-7);
  EXPECT_NEAR(d.linearSpread, 1.0, 1e-5);
  EXPECT_TRUE(d.even);
}

TEST(ChartDensity, ASqueezedPartMakesItUneven) {
  // 2 of 10 quads (20% of the surface) get 1/100 of the others' UV area.
  const ChartDensity d = chartDensity(quads({0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.01f, 0.01f}), 0);
  EXPECT_NEAR(d.sparseDensity, 1e-4, 1e-8);
  EXPECT_NEAR(d.meanDensity, (8 * 0.01 + 2 * 1e-4) / 10.0, 1e-8);
  EXPECT_NEAR(d.linearSpread, std::sqrt(d.meanDensity / 1e-4), 1e-3);
  EXPECT_GT(d.linearSpread, 8.0);
  EXPECT_FALSE(d.even);
  EXPECT_NE(d.describe().find("coarser per side"), std::string::npos) << d.describe();
  // The sparse tenth is what is judged: 5% of the surface squeezed does not count.
  std::initializer_list<float> mostlyEven = {0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f,
                                             0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.1f, 0.01f};
  EXPECT_TRUE(chartDensity(quads(mostlyEven), 0).even);
  EXPECT_FALSE(chartDensity(quads(mostlyEven), 0, {.sparseFraction = 0.02}).even);
}

TEST(ChartDensity, ModerateSpreadIsEven) {
  // A quarter of the surface at a third of the others' UV side (1/9 of their
  // density): uneven; at half their side (1/4 of their density) the spread is under 2: even.
  EXPECT_FALSE(chartDensity(quads({0.3f, 0.3f, 0.3f, 0.1f}), 0).even);
  const ChartDensity half = chartDensity(quads({0.2f, 0.2f, 0.2f, 0.1f}), 0);
  EXPECT_LT(half.linearSpread, 2.0);
  EXPECT_TRUE(half.even);
}

TEST(ChartDensity, ZeroUvAreaAndMissingSets) {
  // A tenth or more of the surface without UV area: infinitely coarse.
  const ChartDensity zero = chartDensity(quads({0.1f, 0.1f, 0.1f, 0.0f}), 0);
  EXPECT_TRUE(std::isinf(zero.linearSpread));
  EXPECT_FALSE(zero.even);
  EXPECT_EQ(zero.describe(), "part of the surface has no UV area");
  // No such set, or no UV area at all: nothing to judge.
  EXPECT_TRUE(chartDensity(quads({0.1f}), 1).even);
  EXPECT_TRUE(chartDensity(quads({0.0f, 0.0f}), 0).even);
}

TEST(ChartDensity, DefaultSceneChartsAreEven) {
  const scene::Scene scene = scene::makeDefaultScene(16);  // small textures: only the charts matter
  for (const scene::Mesh& mesh : scene.meshes) {
    const scene::ChartVerdict chart = scene::chooseShadingChart(mesh);
    if (!chart.unique) continue;
    const ChartDensity d = chartDensity(mesh, chart.uvSet);
    EXPECT_TRUE(d.even) << mesh.name << ": " << d.describe();
  }
}

// Suzanne's radial TEXCOORD_0 is the uneven one; every other sample model's
// unique chart is even (the largest spread there is NormalTangentTest's ~1.5).
TEST(ChartDensity, SampleModels) {
  SG_REQUIRE_ASSETS();
  bool sawSuzanne = false;
  for (const std::filesystem::path& file : test::allSamples()) {
    scene::LoadOptions load;
    load.decodeImages = false;
    const scene::Scene scene = scene::loadGltf(file, load);
    for (const scene::Mesh& mesh : scene.meshes) {
      const scene::ChartVerdict chart = scene::chooseShadingChart(mesh);
      if (!chart.unique) continue;
      const ChartDensity d = chartDensity(mesh, chart.uvSet);
      const bool suzanne = file.stem() == "Suzanne";
      sawSuzanne |= suzanne;
      EXPECT_EQ(d.even, !suzanne) << file.stem().string() << "/" << mesh.name << ": " << d.describe();
      if (suzanne) {
        EXPECT_GT(d.linearSpread, 10.0);
      }
    }
  }
  EXPECT_TRUE(sawSuzanne) << "Suzanne not found among " << test::allSamples().size() << " sample models";
}

}  // namespace
}  // namespace sg::shadel
