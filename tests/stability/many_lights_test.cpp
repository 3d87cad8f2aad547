// Many lights (docs/many-lights.md): 300 point lights with overlapping ranges
// over the lit set, shaded with the clustered light grid (light-cull) and by
// brute force (no grid: every light loop visits all 300), in each path. The
// grid must change the cost only: the two 8-bit images agree within 1/255 —
// with lights straddling tile edges (a light listed in clusters of several
// tiles) and the grid really culling (clusters list a fraction of the lights).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <set>

#include <shadelgraph/render/shaders/light_grid.h>

#include "stability_scenes.hpp"
#include "stability_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kLights = 300;
constexpr uint32_t kWidth = 320, kHeight = 192;  // 64-pixel tiles: 5 x 3

// What a captured grid lists.
struct GridCensus {
  shader::SgLightGridHeader header{};
  uint32_t clusters = 0, listed = 0, everyLight = 0, empty = 0;
  uint64_t indices = 0;  // over the listed clusters
  uint32_t lightsInSeveralTiles = 0;
  bool ascending = true, inRange = true;
};

GridCensus census(const std::vector<uint32_t>& words) {
  GridCensus c;
  const size_t headerWords = sizeof(shader::SgLightGridHeader) / sizeof(uint32_t);
  std::memcpy(&c.header, words.data(), sizeof c.header);
  const glm::uvec4 d = c.header.dims;
  c.clusters = d.x * d.y * d.z;
  std::vector<std::set<uint32_t>> tilesOf(kLights);
  for (uint32_t cluster = 0; cluster < c.clusters; ++cluster) {
    const size_t record = headerWords + size_t(cluster) * (d.w + 1);
    const uint32_t count = words.at(record);
    if (count == shader::kLightGridEveryLight) {
      ++c.everyLight;
      continue;
    }
    if (count == 0) ++c.empty;
    ++c.listed;
    c.indices += count;
    for (uint32_t k = 0; k < count; ++k) {
      const uint32_t light = words.at(record + 1 + k);
      if (light >= kLights) {
        c.inRange = false;
        continue;
      }
      if (k > 0 && light <= words.at(record + k)) c.ascending = false;
      tilesOf[light].insert(cluster % (d.x * d.y));
    }
  }
  for (const auto& tiles : tilesOf) c.lightsInSeveralTiles += tiles.size() > 1;
  return c;
}

class ManyLights : public ::testing::TestWithParam<scene::ShadingMode> {};

TEST_P(ManyLights, ClusteredShadingEqualsBruteForceWithinOneLevel) {
  const scene::Scene s = makeLitSetWithPointLights(kLights);
  // Manual exposure: the two images are compared as shaded, not as metered.
  const nlohmann::json exposure = {{"mode", "manual"}, {"ev100", 2.0}};
  StabilitySession culled(s, GetParam(), {}, exposure, kHdrCapturedFrame, {{"threshold", 0}});
  StabilitySession brute(s, GetParam(), {}, exposure, kHdrCapturedFrame, {{"threshold", kLights}});
  const StabilityFrame a = culled.render(kWidth, kHeight);
  const StabilityFrame b = brute.render(kWidth, kHeight);

  EXPECT_TRUE(brute.lightGrid().empty()) << "a frame at its threshold culls nothing";
  const std::vector<uint32_t> grid = culled.lightGrid();
  ASSERT_FALSE(grid.empty()) << "threshold 0: the frame has a light grid";
  const GridCensus c = census(grid);
  std::printf("grid %ux%ux%u, %u slots: %u clusters listed (%u empty), %u use every light, "
              "%.1f lights per listed cluster, %u of %u lights in several tiles\n",
              c.header.dims.x, c.header.dims.y, c.header.dims.z, c.header.dims.w, c.listed, c.empty, c.everyLight,
              c.listed ? double(c.indices) / c.listed : 0.0, c.lightsInSeveralTiles, kLights);
  EXPECT_EQ(c.header.dims, glm::uvec4(5, 3, shader::kLightGridSlices, shader::kLightGridMaxPerCluster));
  EXPECT_TRUE(c.inRange && c.ascending) << "indices are light numbers, ascending";
  // The grid culls: most clusters list their lights, on average a small part of them.
  EXPECT_GT(c.listed, c.clusters / 2);
  EXPECT_LT(double(c.indices) / c.listed, kLights / 4.0);
  // The hard case: lights straddling tile edges (listed by clusters of more than one tile).
  EXPECT_GE(c.lightsInSeveralTiles, kLights / 3);

  ASSERT_EQ(a.ldr.rgba8.size(), b.ldr.rgba8.size());
  int worst = 0;
  size_t differing = 0;
  for (size_t i = 0; i < a.ldr.rgba8.size(); ++i) {
    const int d = std::abs(int(a.ldr.rgba8[i]) - int(b.ldr.rgba8[i]));
    worst = std::max(worst, d);
    differing += d != 0;
  }
  std::printf("culled vs brute force: largest difference %d/255, %zu of %zu channels differ\n", worst, differing,
              a.ldr.rgba8.size());
  EXPECT_LE(worst, 1);
  // Not a black frame (which would agree trivially).
  EXPECT_GT(*std::max_element(b.ldr.rgba8.begin(), b.ldr.rgba8.end()), 100);
}

INSTANTIATE_TEST_SUITE_P(Paths, ManyLights,
                         ::testing::Values(scene::ShadingMode::Forward, scene::ShadingMode::Decoupled),
                         [](const auto& param_info) {
                           return std::string(param_info.param == scene::ShadingMode::Forward ? "Forward" : "Decoupled");
                         });

}  // namespace
}  // namespace sg::test
