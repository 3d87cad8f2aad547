#pragma once
// One level of a triangle-ID map while it is being baked: the steps of
// triangle_id_map.hpp work on this.
#include <cstdint>
#include <vector>

#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/uv_rasterizer.hpp>

namespace sg::shadel {

enum class TexelSource : uint8_t { Empty, Normal, Conservative, Claimed, Dilated };

struct IdMapLevel {
  uint32_t size = 0;
  std::vector<FixedTriangle> triangles;  // in this level's texel units
  std::vector<bool> zeroArea;            // per triangle: takes no part
  std::vector<uint32_t> owner;           // per texel: triangle id or kNoTriangle
  std::vector<TexelSource> source;       // per texel
  std::vector<uint32_t> ownedTexels;     // per triangle, through normal/conservative/claims
  // Per triangle: kNoTexel, or the texel under its UV centroid for a
  // triangle too small for this level: snapped to a point, or to a segment
  // on texel borders, it has area in no texel, but it must touch one.
  std::vector<uint32_t> centroidTexel;

  static constexpr uint32_t kNoTexel = 0xFFFFFFFFu;

  IdMapLevel(const ChartTriangles& chart, uint32_t levelSize);
  uint32_t index(uint32_t x, uint32_t y) const { return y * size + x; }
  glm::dvec2 centre(uint32_t texel) const { return {texel % size + 0.5, texel / size + 0.5}; }

  // The texels triangle t touches at this level: touchedTexels(), or its
  // centroidTexel. Skipped texels are not visited.
  template <class Skip, class Visit>
  void forEachTouched(uint32_t t, Skip&& skip, Visit&& visit) const {
    if (centroidTexel[t] != kNoTexel) {
      const uint32_t x = centroidTexel[t] % size, y = centroidTexel[t] / size;
      if (!skip(x, y)) visit(x, y);
      return;
    }
    touchedTexels(triangles[t], size, skip, visit);
  }
  template <class Visit>
  void forEachTouched(uint32_t t, Visit&& visit) const {
    forEachTouched(t, [](uint32_t, uint32_t) { return false; }, visit);
  }
};

// Steps (1) and (2): normal coverage, then conservative where it left nothing.
void rasterizeCoverage(IdMapLevel& level);
// Step (3); returns the triangles still owning nothing.
uint32_t claimTexelsForOrphans(IdMapLevel& level, const ChartTriangles& chart);
// Step (4).
void dilate(IdMapLevel& level, uint32_t rings);

}  // namespace sg::shadel
