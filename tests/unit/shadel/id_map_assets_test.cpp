// Triangle-ID maps of every sample model whose mesh has a unique chart.
#include <chrono>
#include <cstdio>

#include <gtest/gtest.h>

#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/level0_resolution.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

#include "id_map_checks.hpp"
#include "shadel_test_support.hpp"

namespace sg::shadel {
namespace {

// "Every triangle owns a texel at every level" cannot hold where a level has
// fewer texels than triangles in some region (Suzanne's chart has 1229 of
// its 3936 triangles below one texel at 1024², a quarter below 1/4 texel),
// so this checks what can hold: no holes, no empty neighbours of chart
// texels, and orphans only where Hall's condition fails (checkIdMapLevel),
// and it reports the counts.
TEST(IdMapAssets, EveryTriangleOwnsATexelWhereTexelsSuffice) {
  SG_REQUIRE_ASSETS();
  size_t meshesBaked = 0;
  bool sawSuzanne = false;
  for (const std::filesystem::path& file : test::allSamples()) {
    scene::LoadOptions load;
    load.decodeImages = false;
    const scene::Scene scene = scene::loadGltf(file, load);
    for (const scene::Mesh& mesh : scene.meshes) {
      const scene::ChartVerdict chart = scene::chooseShadingChart(mesh);
      if (!chart.unique) continue;
      const std::string name = file.stem().string() + "/" + mesh.name;
      SCOPED_TRACE(name);
      IdMapOptions options;
      options.level0Size = chooseLevel0Size(mesh, chart, meshTextureDensity(scene, mesh));
      const auto start = std::chrono::steady_clock::now();
      const TriangleIdMap map = bakeTriangleIdMap(mesh, chart, options);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const ChartTriangles triangles = chartTriangles(mesh, chart.uvSet, chart.tileOffset);
      IdMapOptions withoutClaims = options;
      withoutClaims.claimOrphans = false;
      const TriangleIdMap unclaimed = bakeTriangleIdMap(mesh, chart, withoutClaims);
      std::printf("%-48s %6u triangles (%u zero-area), level 0 %5u, %2u levels, baked in %.3f s\n", name.c_str(),
                  map.triangleCount, map.zeroAreaTriangles, map.levels.level0Size, map.levels.levelCount, seconds);
      for (uint32_t level = 0; level < map.levels.levelCount; ++level) {
        const test::LevelOwnership ownership = test::checkIdMapLevel(map, level, triangles, options.dilation > 0);
        const IdMapLevelStats& s = map.stats[level];
        EXPECT_EQ(ownership.owning, s.owningTriangles);
        EXPECT_EQ(ownership.orphans, s.orphanTriangles);
        EXPECT_EQ(s.zeroAreaUncovered, 0u);
        if (map.triangleCount > 100)
          std::printf("    level %u (%4u²): %7llu normal %5llu conservative %4llu claimed %5llu dilated texels; "
                      "%4u triangles own, %4u orphans (%4u without claims)\n",
                      level, s.size, static_cast<unsigned long long>(s.normalTexels),
                      static_cast<unsigned long long>(s.conservativeTexels),
                      static_cast<unsigned long long>(s.claimedTexels), static_cast<unsigned long long>(s.dilatedTexels),
                      s.owningTriangles, s.orphanTriangles, unclaimed.stats[level].orphanTriangles);
        EXPECT_LE(s.orphanTriangles, unclaimed.stats[level].orphanTriangles);
      }
      ++meshesBaked;
      sawSuzanne |= file.stem() == "Suzanne";
    }
  }
  EXPECT_TRUE(sawSuzanne) << "Suzanne has a unique chart and must be among them";
  EXPECT_GE(meshesBaked, 10u);
}

}  // namespace
}  // namespace sg::shadel
