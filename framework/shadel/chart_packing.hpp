#pragma once
// Step 3 of automatic charting (auto_chart.hpp): rectangles into [0,1]².
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sg::shadel {

struct ChartPacking {
  bool fits = false;
  double scale = 0.0;               // UV units per unit of the input sizes
  std::vector<glm::dvec2> origins;  // per rectangle: where its scaled content starts
};

// Shelf packing, tallest first, each rectangle in a cell `gutter` (UV units)
// larger than its scaled size and centred in it: rectangles end up at least
// `gutter` apart and gutter/2 from the border. The scale is the largest that
// fits, found by bisection (shelf packing is not monotone in the scale, so
// it is "a largest found", within 0.1%). fits is false only when even
// zero-size rectangles' cells do not fit.
ChartPacking packCharts(std::span<const glm::dvec2> sizes, double gutter);

}  // namespace sg::shadel
