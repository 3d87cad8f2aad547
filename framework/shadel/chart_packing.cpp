#include <algorithm>
#include <cmath>
#include <numeric>

#include <shadelgraph/shadel/chart_packing.hpp>

namespace sg::shadel {
namespace {

// Places the cells shelf by shelf in `order`; false when they overflow [0,1]².
bool place(std::span<const glm::dvec2> sizes, const std::vector<uint32_t>& order, double scale, double gutter,
           std::vector<glm::dvec2>* origins) {
  double x = 0.0, y = 0.0, shelf = 0.0;
  for (uint32_t i : order) {
    const glm::dvec2 cell = sizes[i] * scale + gutter;
    if (cell.x > 1.0) return false;
    if (x + cell.x > 1.0) {  // next shelf
      y += shelf;
      x = 0.0;
      shelf = 0.0;
    }
    if (shelf == 0.0) shelf = cell.y;  // the tallest of this shelf comes first
    if (y + shelf > 1.0) return false;
    if (origins) (*origins)[i] = glm::dvec2(x, y) + gutter * 0.5;
    x += cell.x;
  }
  return true;
}

}  // namespace

ChartPacking packCharts(std::span<const glm::dvec2> sizes, double gutter) {
  ChartPacking packing;
  std::vector<uint32_t> order(sizes.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return sizes[a].y > sizes[b].y; });
  if (!place(sizes, order, 0.0, gutter, nullptr)) return packing;

  // No scale beyond the one at which the rectangles alone fill the square.
  double area = 0.0, longest = 0.0;
  for (const glm::dvec2& s : sizes) area += s.x * s.y, longest = std::max({longest, s.x, s.y});
  double lo = 0.0, hi = area > 0.0 ? std::sqrt(1.0 / area) : (longest > 0.0 ? 1.0 / longest : 1.0);
  if (place(sizes, order, hi, gutter, nullptr)) lo = hi;
  while (hi - lo > lo * 1e-3 + 1e-12) {
    const double mid = 0.5 * (lo + hi);
    (place(sizes, order, mid, gutter, nullptr) ? lo : hi) = mid;
  }
  packing.fits = true;
  packing.scale = lo;
  packing.origins.resize(sizes.size());
  place(sizes, order, lo, gutter, &packing.origins);
  return packing;
}

}  // namespace sg::shadel
