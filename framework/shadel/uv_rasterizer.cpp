#include <algorithm>
#include <cmath>

#include <shadelgraph/shadel/uv_rasterizer.hpp>

namespace sg::shadel {

FixedTriangle snapTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  FixedTriangle t;
  const auto snap = [](glm::dvec2 p) {
    return glm::i64vec2(std::llround(p.x * kSubTexels), std::llround(p.y * kSubTexels));
  };
  t.v = {snap(a), snap(b), snap(c)};
  int64_t area = detail::edgeFunction(t.v[0], t.v[1], t.v[2]);
  if (area < 0) {
    std::swap(t.v[1], t.v[2]);
    area = -area;
  }
  t.doubleArea = area;
  t.min = glm::min(glm::min(t.v[0], t.v[1]), t.v[2]);
  t.max = glm::max(glm::max(t.v[0], t.v[1]), t.v[2]);
  return t;
}

double distanceToTriangle(const FixedTriangle& t, glm::dvec2 p) {
  glm::dvec2 v[3];
  for (int k = 0; k < 3; ++k) v[k] = glm::dvec2(t.v[static_cast<size_t>(k)]) / static_cast<double>(kSubTexels);
  const auto cross = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
    return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
  };
  if (t.doubleArea > 0 && cross(v[1], v[2], p) >= 0 && cross(v[2], v[0], p) >= 0 && cross(v[0], v[1], p) >= 0)
    return 0.0;
  double best = HUGE_VAL;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 a = v[k], b = v[(k + 1) % 3], d = b - a;
    const double length2 = glm::dot(d, d);
    const double s = length2 > 0.0 ? std::clamp(glm::dot(p - a, d) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(p - (a + s * d)));
  }
  return best;
}

}  // namespace sg::shadel
