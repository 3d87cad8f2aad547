#include <algorithm>
#include <cmath>
#include <numeric>

#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/chart_parameterization.hpp>

namespace sg::shadel {
namespace {

double cross2(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain; counter-clockwise, no collinear points.
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points) {
  std::sort(points.begin(), points.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<glm::dvec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// The direction (unit vector) of the x axis of the minimum-area rectangle
// around the hull: one of its edges' (rotating calipers, done plainly).
glm::dvec2 minimumAreaDirection(const std::vector<glm::dvec2>& hull) {
  glm::dvec2 best(1.0, 0.0);
  double bestArea = HUGE_VAL;
  for (size_t i = 0; i < hull.size(); ++i) {
    glm::dvec2 d = hull[(i + 1) % hull.size()] - hull[i];
    const double length = glm::length(d);
    if (length <= 0.0) continue;
    d /= length;
    const glm::dvec2 n(-d.y, d.x);
    double minU = HUGE_VAL, maxU = -HUGE_VAL, minV = HUGE_VAL, maxV = -HUGE_VAL;
    for (const glm::dvec2& p : hull) {
      minU = std::min(minU, glm::dot(p, d)), maxU = std::max(maxU, glm::dot(p, d));
      minV = std::min(minV, glm::dot(p, n)), maxV = std::max(maxV, glm::dot(p, n));
    }
    const double area = (maxU - minU) * (maxV - minV);
    if (area < bestArea) bestArea = area, best = d;
  }
  return best;
}

class Parameterizer {
 public:
  explicit Parameterizer(const FlatTriangles& triangles) : triangles_(triangles) {}

  // A frame for the chart, or nothing when its projection overlaps itself.
  bool flatten(const std::vector<uint32_t>& chart, ChartFrame& frame) const {
    glm::dvec3 normalSum(0.0);
    double worldArea = 0.0;
    for (uint32_t t : chart) {
      normalSum += triangles_.areaNormal(t);
      worldArea += triangles_.area(t);
    }
    const glm::dvec3 n = glm::length(normalSum) > 0.0 ? glm::normalize(normalSum) : glm::dvec3(0, 0, 1);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 tangent = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 bitangent = glm::cross(n, tangent);

    std::vector<glm::dvec2> corners;
    corners.reserve(chart.size() * 3);
    for (uint32_t t : chart)
      for (const glm::dvec3& p : triangles_.positions[t]) corners.emplace_back(glm::dot(p, tangent), glm::dot(p, bitangent));
    if (chart.size() > 1 && overlaps(corners)) return false;

    double projectedArea = 0.0;
    for (size_t i = 0; i < corners.size(); i += 3) projectedArea += 0.5 * std::abs(cross2(corners[i], corners[i + 1], corners[i + 2]));
    const double density = projectedArea > 0.0 && worldArea > 0.0 ? std::sqrt(worldArea / projectedArea) : 1.0;

    glm::dvec2 u = minimumAreaDirection(convexHull(corners)), v(-u.y, u.x);
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::dvec2& c : corners) {
      const glm::dvec2 q(glm::dot(c, u), glm::dot(c, v));
      lo = glm::min(lo, q), hi = glm::max(hi, q);
    }
    if (hi.y - lo.y > hi.x - lo.x) {  // lie flat: shelves waste less on wide, low rectangles
      std::swap(u, v);
      std::swap(lo.x, lo.y);
      std::swap(hi.x, hi.y);
    }
    frame.triangles = chart;
    frame.axisU = density * (u.x * tangent + u.y * bitangent);
    frame.axisV = density * (v.x * tangent + v.y * bitangent);
    frame.offset = density * lo;
    frame.size = density * (hi - lo);
    return true;
  }

  // Two halves, cut through the median centroid along the longest axis.
  std::pair<std::vector<uint32_t>, std::vector<uint32_t>> split(std::vector<uint32_t> chart) const {
    glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (uint32_t t : chart) lo = glm::min(lo, centroid(t)), hi = glm::max(hi, centroid(t));
    const glm::dvec3 extent = hi - lo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto middle = chart.begin() + static_cast<std::ptrdiff_t>(chart.size() / 2);
    std::nth_element(chart.begin(), middle, chart.end(),
                     [&](uint32_t a, uint32_t b) { return centroid(a)[axis] < centroid(b)[axis]; });
    return {std::vector<uint32_t>(chart.begin(), middle), std::vector<uint32_t>(middle, chart.end())};
  }

 private:
  glm::dvec3 centroid(uint32_t t) const {
    const auto& p = triangles_.positions[t];
    return (p[0] + p[1] + p[2]) / 3.0;
  }

  // The same test the finished chart must pass, on the chart alone scaled
  // into [0,1]² (so its epsilons are relative to the chart).
  static bool overlaps(const std::vector<glm::dvec2>& corners) {
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const glm::dvec2& c : corners) lo = glm::min(lo, c), hi = glm::max(hi, c);
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    if (!(extent > 0.0)) return false;
    scene::Primitive flat;
    for (const glm::dvec2& c : corners) flat.uv0.push_back(glm::vec2((c - lo) / extent));
    // No positions: none counts as degenerate in 3D (a flattened one has no UV area anyway).
    flat.indices.resize(flat.uv0.size());
    std::iota(flat.indices.begin(), flat.indices.end(), 0u);
    scene::UvChartOptions options;
    options.maxZeroAreaFraction = 1.0;
    options.maxOverlappingPairs = 1;
    return scene::analyzeUvSet(flat, 0, options).overlappingPairs > 0;
  }

  const FlatTriangles& triangles_;
};

}  // namespace

std::vector<ChartFrame> parameterizeCharts(const FlatTriangles& triangles, const std::vector<uint32_t>& chartOf,
                                           uint32_t& splits) {
  splits = 0;
  const uint32_t chartCount = chartOf.empty() ? 0 : *std::max_element(chartOf.begin(), chartOf.end()) + 1;
  std::vector<std::vector<uint32_t>> pending(chartCount);
  for (uint32_t t = 0; t < chartOf.size(); ++t) pending[chartOf[t]].push_back(t);
  std::reverse(pending.begin(), pending.end());  // popped from the back: chart 0 first

  const Parameterizer parameterizer(triangles);
  std::vector<ChartFrame> frames;
  while (!pending.empty()) {
    std::vector<uint32_t> chart = std::move(pending.back());
    pending.pop_back();
    ChartFrame frame;
    if (parameterizer.flatten(chart, frame)) {
      frames.push_back(std::move(frame));
      continue;
    }
    ++splits;
    auto [first, second] = parameterizer.split(std::move(chart));
    pending.push_back(std::move(second));
    pending.push_back(std::move(first));
  }
  return frames;
}

}  // namespace sg::shadel
