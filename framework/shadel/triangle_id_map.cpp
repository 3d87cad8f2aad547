#include <stdexcept>
#include <string>

#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/id_map_level.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

namespace sg::shadel {
namespace {

IdMapLevelStats statsOf(const IdMapLevel& level, const ChartTriangles& chart, uint32_t orphans) {
  IdMapLevelStats stats;
  stats.size = level.size;
  for (TexelSource source : level.source) switch (source) {
      case TexelSource::Empty: ++stats.emptyTexels; break;
      case TexelSource::Normal: ++stats.normalTexels; break;
      case TexelSource::Conservative: ++stats.conservativeTexels; break;
      case TexelSource::Claimed: ++stats.claimedTexels; break;
      case TexelSource::Dilated: ++stats.dilatedTexels; break;
    }
  for (size_t t = 0; t < level.triangles.size(); ++t) {
    if (!level.zeroArea[t]) {
      if (level.ownedTexels[t] > 0) ++stats.owningTriangles;
      continue;
    }
    const auto& uv = chart.uv[t];
    const glm::dvec2 centroid = (uv[0] + uv[1] + uv[2]) / 3.0 * static_cast<double>(level.size);
    const glm::ivec2 texel = glm::clamp(glm::ivec2(glm::floor(centroid)), glm::ivec2(0), glm::ivec2(static_cast<int>(level.size) - 1));
    if (level.owner[level.index(static_cast<uint32_t>(texel.x), static_cast<uint32_t>(texel.y))] == kNoTriangle)
      ++stats.zeroAreaUncovered;
  }
  stats.orphanTriangles = orphans;
  return stats;
}

}  // namespace

TriangleIdMap bakeTriangleIdMap(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const IdMapOptions& options) {
  if (chart.uvSet != 0 && chart.uvSet != 1)
    throw std::invalid_argument("bakeTriangleIdMap: the chart names no UV set (" + chart.reason + ")");
  TriangleIdMap map;
  map.levels = makeDetailLevels(options.level0Size, options.minLevelSize);
  if (!map.levels.valid())
    throw std::invalid_argument("bakeTriangleIdMap: level 0 size " + std::to_string(options.level0Size) +
                                " with minimum " + std::to_string(options.minLevelSize) + " gives no valid level chain");
  const ChartTriangles triangles = chartTriangles(mesh, chart.uvSet, chart.tileOffset);
  map.triangleCount = static_cast<uint32_t>(triangles.size());
  map.primitiveTriangleBase = triangles.primitiveTriangleBase;
  for (size_t t = 0; t < triangles.size(); ++t) map.zeroAreaTriangles += triangles.zeroArea(t);

  for (uint32_t l = 0; l < map.levels.levelCount; ++l) {
    IdMapLevel level(triangles, map.levels.levelSize(l));
    rasterizeCoverage(level);
    uint32_t orphans = 0;
    if (options.claimOrphans) {
      orphans = claimTexelsForOrphans(level, triangles);
    } else {
      for (size_t t = 0; t < level.triangles.size(); ++t) orphans += !level.zeroArea[t] && level.ownedTexels[t] == 0;
    }
    dilate(level, options.dilation);
    map.stats.push_back(statsOf(level, triangles, orphans));
    map.levelOffsets.push_back(map.texels.size());
    map.texels.insert(map.texels.end(), level.owner.begin(), level.owner.end());
  }
  return map;
}

}  // namespace sg::shadel
