#include <algorithm>
#include <cmath>
#include <limits>

#include <shadelgraph/shadel/id_map_level.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

namespace sg::shadel {

IdMapLevel::IdMapLevel(const ChartTriangles& chart, uint32_t levelSize)
    : size(levelSize),
      zeroArea(chart.size()),
      owner(size_t{levelSize} * levelSize, kNoTriangle),
      source(size_t{levelSize} * levelSize, TexelSource::Empty),
      ownedTexels(chart.size(), 0),
      centroidTexel(chart.size(), kNoTexel) {
  const double scale = levelSize;
  triangles.reserve(chart.size());
  for (size_t t = 0; t < chart.size(); ++t) {
    const auto& uv = chart.uv[t];
    triangles.push_back(snapTriangle(uv[0] * scale, uv[1] * scale, uv[2] * scale));
    zeroArea[t] = chart.zeroArea(t);
    if (zeroArea[t] || triangles.back().doubleArea > 0) continue;
    bool touchesAny = false;
    touchedTexels(triangles.back(), size, [&](uint32_t, uint32_t) { touchesAny = true; });
    if (touchesAny) continue;
    const glm::dvec2 centroid = (uv[0] + uv[1] + uv[2]) / 3.0 * scale;
    const auto clampToMap = [&](double v) {
      return static_cast<uint32_t>(std::clamp(std::floor(v), 0.0, static_cast<double>(size - 1)));
    };
    centroidTexel[t] = index(clampToMap(centroid.x), clampToMap(centroid.y));
  }
}

void rasterizeCoverage(IdMapLevel& level) {
  const auto count = static_cast<uint32_t>(level.triangles.size());
  for (uint32_t t = 0; t < count; ++t) {
    if (level.zeroArea[t]) continue;
    coverage(level.triangles[t], level.size, [&](uint32_t x, uint32_t y) {
      const uint32_t i = level.index(x, y);
      level.owner[i] = t;  // a unique chart has no overlaps; if it had, the last triangle wins
      level.source[i] = TexelSource::Normal;
    });
  }
  // Conservative fill: nearest triangle to the texel centre, lowest id on ties.
  std::vector<float> nearest(level.owner.size(), std::numeric_limits<float>::infinity());
  for (uint32_t t = 0; t < count; ++t) {
    if (level.zeroArea[t]) continue;
    const FixedTriangle& triangle = level.triangles[t];
    level.forEachTouched(
        t, [&](uint32_t x, uint32_t y) { return level.source[level.index(x, y)] == TexelSource::Normal; },
        [&](uint32_t x, uint32_t y) {
          const uint32_t i = level.index(x, y);
          const auto distance = static_cast<float>(distanceToTriangle(triangle, level.centre(i)));
          if (distance < nearest[i]) {
            nearest[i] = distance;
            level.owner[i] = t;
            level.source[i] = TexelSource::Conservative;
          }
        });
  }
  for (uint32_t owner : level.owner)
    if (owner != kNoTriangle) ++level.ownedTexels[owner];
}

void dilate(IdMapLevel& level, uint32_t rings) {
  const auto size = static_cast<int64_t>(level.size);
  for (uint32_t ring = 0; ring < rings; ++ring) {
    std::vector<uint32_t> next = level.owner;
    bool changed = false;
    for (int64_t y = 0; y < size; ++y)
      for (int64_t x = 0; x < size; ++x) {
        const auto i = static_cast<uint32_t>(y * size + x);
        if (level.owner[i] != kNoTriangle) continue;
        double best = HUGE_VAL;
        for (int64_t dy = -1; dy <= 1; ++dy)
          for (int64_t dx = -1; dx <= 1; ++dx) {
            const int64_t nx = x + dx, ny = y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
            const uint32_t candidate = level.owner[static_cast<size_t>(ny * size + nx)];
            if (candidate == kNoTriangle) continue;
            const double distance = distanceToTriangle(level.triangles[candidate], level.centre(i));
            if (distance < best || (distance == best && candidate < next[i])) {
              best = distance;
              next[i] = candidate;
            }
          }
        if (next[i] != kNoTriangle) {
          level.source[i] = TexelSource::Dilated;
          changed = true;
        }
      }
    level.owner = std::move(next);
    if (!changed) break;
  }
}

}  // namespace sg::shadel
