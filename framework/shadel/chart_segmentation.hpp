#pragma once
// Step 1 of automatic charting (auto_chart.hpp): which triangles form a chart.
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::shadel {

// A mesh's triangles in one list (primitive by primitive: mesh triangle ids).
struct FlatTriangles {
  std::vector<std::array<glm::dvec3, 3>> positions;

  explicit FlatTriangles(const scene::Mesh& mesh);
  size_t size() const { return positions.size(); }
  // Geometric normal scaled by twice the area (zero for a degenerate triangle).
  glm::dvec3 areaNormal(size_t t) const;
  double area(size_t t) const { return 0.5 * glm::length(areaNormal(t)); }
};

// Per triangle, the triangles sharing one of its edges: same primitive,
// vertices welded by position, and only edges exactly two triangles share
// (a non-manifold edge is a chart border).
std::vector<std::vector<uint32_t>> edgeAdjacency(const scene::Mesh& mesh);

// Chart index per triangle, charts numbered from 0. Seeds are taken largest
// first; a chart grows over adjacent triangles whose unit normal is within
// coneAngleDegrees of the seed's. Triangles of zero area (no normal) join
// an adjacent chart, or form their own when isolated.
std::vector<uint32_t> growCharts(const FlatTriangles& triangles, const std::vector<std::vector<uint32_t>>& adjacency,
                                 double coneAngleDegrees);

}  // namespace sg::shadel
