#pragma once
// A mesh's triangles in its shading chart: the chosen UV set shifted by the
// chart's tile offset into [0,1]², numbered mesh-wide (primitive by
// primitive, in index order): the triangle IDs of the ID maps.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/mesh.hpp>
#include <shadelgraph/scene/uv_chart.hpp>

namespace sg::shadel {

// Triangles with at most this UV area (in UV units²) have no interior to own
// texels: the same threshold scene::analyzeUvSet counts as zero-area.
inline constexpr double kZeroUvArea = scene::UvChartOptions{}.zeroAreaEpsilon;

struct ChartTriangles {
  std::vector<std::array<glm::dvec2, 3>> uv;    // per mesh triangle, in [0,1]²
  std::vector<uint32_t> primitiveTriangleBase;  // mesh triangle id of each primitive's first triangle

  size_t size() const { return uv.size(); }
  double area(size_t triangle) const;  // unsigned, UV units²
  bool zeroArea(size_t triangle) const { return area(triangle) <= kZeroUvArea; }
  double totalArea() const;
};

// Throws std::invalid_argument when a primitive lacks the UV set.
ChartTriangles chartTriangles(const scene::Mesh& mesh, int uvSet, glm::vec2 tileOffset);

}  // namespace sg::shadel
