#pragma once
// Step 2 of automatic charting (auto_chart.hpp): each chart flattened into
// its own rectangle.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/shadel/chart_segmentation.hpp>

namespace sg::shadel {

// A chart laid flat: place(p) maps a position of one of its triangles into
// [0, size.x] x [0, size.y], in world units of equal area (the projection
// scaled by sqrt(world area / projected area)).
struct ChartFrame {
  std::vector<uint32_t> triangles;   // mesh triangle ids
  glm::dvec3 axisU{1, 0, 0}, axisV{0, 1, 0};  // projection, rotation and density scale in one
  glm::dvec2 offset{0.0};
  glm::dvec2 size{0.0};

  glm::dvec2 place(const glm::dvec3& p) const { return glm::dvec2(glm::dot(p, axisU), glm::dot(p, axisV)) - offset; }
};

// One frame per chart (charts from growCharts), plus more where a chart's
// projection overlapped itself and was cut; `splits` counts the cuts.
std::vector<ChartFrame> parameterizeCharts(const FlatTriangles& triangles, const std::vector<uint32_t>& chartOf,
                                           uint32_t& splits);

}  // namespace sg::shadel
