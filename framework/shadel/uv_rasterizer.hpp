#pragma once
// Rasterizing a triangle given in texel units of a square map, on the CPU:
// - coverage(): texels whose centre is inside, with the top-left rule on
//   shared edges, like a GPU: each centre on an edge two triangles share
//   belongs to exactly one of them;
// - touchedTexels(): conservative, every texel the triangle has any area in
//   (lavapipe has no VK_EXT_conservative_rasterization).
// Vertices are snapped to 1/256 texel (a GPU's 8 sub-pixel bits) so the edge
// functions are exact in 64-bit integers: no sample is lost or doubled
// between neighbours to rounding.
#include <algorithm>
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace sg::shadel {

inline constexpr int64_t kSubTexels = 256;

struct FixedTriangle {
  std::array<glm::i64vec2, 3> v{};  // counter-clockwise in a y-down frame once oriented: edge functions >= 0 inside
  int64_t doubleArea = 0;           // > 0, or 0 when the snapped triangle is degenerate
  glm::i64vec2 min{0}, max{0};      // bounding box
};

// From texel-unit coordinates (uv * levelSize).
FixedTriangle snapTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);

// Euclidean distance in texels from p (texel units) to the closed triangle:
// 0 inside.
double distanceToTriangle(const FixedTriangle& t, glm::dvec2 p);

namespace detail {
inline int64_t edgeFunction(glm::i64vec2 a, glm::i64vec2 b, glm::i64vec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}
// Top edges (horizontal, interior below in a y-down frame) and left edges
// own the samples exactly on them.
inline bool isTopLeft(glm::i64vec2 a, glm::i64vec2 b) {
  const glm::i64vec2 d = b - a;
  return d.y < 0 || (d.y == 0 && d.x > 0);
}
inline int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }
inline int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }
}  // namespace detail

// Calls visit(x, y) for each texel of a size x size map whose centre the
// triangle covers. Degenerate triangles cover nothing.
template <class Visit>
void coverage(const FixedTriangle& t, uint32_t size, Visit&& visit) {
  if (t.doubleArea <= 0) return;
  // Centres are at (i + 1/2) texels: i from ceil(min - 1/2) to floor(max - 1/2).
  const int64_t half = kSubTexels / 2, last = int64_t{size} - 1;
  const int64_t x0 = std::max<int64_t>(detail::ceilDiv(t.min.x - half, kSubTexels), 0);
  const int64_t y0 = std::max<int64_t>(detail::ceilDiv(t.min.y - half, kSubTexels), 0);
  const int64_t x1 = std::min<int64_t>(detail::floorDiv(t.max.x - half, kSubTexels), last);
  const int64_t y1 = std::min<int64_t>(detail::floorDiv(t.max.y - half, kSubTexels), last);
  const bool topLeft[3] = {detail::isTopLeft(t.v[1], t.v[2]), detail::isTopLeft(t.v[2], t.v[0]),
                           detail::isTopLeft(t.v[0], t.v[1])};
  for (int64_t y = y0; y <= y1; ++y)
    for (int64_t x = x0; x <= x1; ++x) {
      const glm::i64vec2 p(x * kSubTexels + half, y * kSubTexels + half);
      const int64_t w[3] = {detail::edgeFunction(t.v[1], t.v[2], p), detail::edgeFunction(t.v[2], t.v[0], p),
                            detail::edgeFunction(t.v[0], t.v[1], p)};
      bool inside = true;
      for (int e = 0; e < 3 && inside; ++e) inside = w[e] > 0 || (w[e] == 0 && topLeft[e]);
      if (inside) visit(static_cast<uint32_t>(x), static_cast<uint32_t>(y));
    }
}

// Calls visit(x, y) for each texel of a size x size map whose interior (the
// open square) the closed triangle meets: every texel the triangle has any
// area in, not those it only touches along their border. Separating axes:
// the box's and the edges' normals. A degenerate (snapped) triangle is its
// segment or point and touches the texels whose interior it passes through.
// Texels for which skip(x, y) is true are not tested (nor visited).
template <class Skip, class Visit>
void touchedTexels(const FixedTriangle& t, uint32_t size, Skip&& skip, Visit&& visit) {
  // Texel i is the open interval (i, i + 1) * kSubTexels: i from floor(min) to ceil(max) - 1.
  const int64_t last = int64_t{size} - 1;
  const int64_t x0 = std::max<int64_t>(detail::floorDiv(t.min.x, kSubTexels), 0);
  const int64_t y0 = std::max<int64_t>(detail::floorDiv(t.min.y, kSubTexels), 0);
  const int64_t x1 = std::min<int64_t>(detail::ceilDiv(t.max.x, kSubTexels) - 1, last);
  const int64_t y1 = std::min<int64_t>(detail::ceilDiv(t.max.y, kSubTexels) - 1, last);
  const std::array<std::array<glm::i64vec2, 2>, 3> edges{{{t.v[1], t.v[2]}, {t.v[2], t.v[0]}, {t.v[0], t.v[1]}}};
  for (int64_t y = y0; y <= y1; ++y)
    for (int64_t x = x0; x <= x1; ++x) {
      if (skip(static_cast<uint32_t>(x), static_cast<uint32_t>(y))) continue;
      const glm::i64vec2 lo(x * kSubTexels, y * kSubTexels), hi = lo + kSubTexels;
      bool touches = true;
      for (const auto& [a, b] : edges) {
        if (a == b) continue;
        int64_t lowest = INT64_MAX, highest = INT64_MIN;
        for (glm::i64vec2 corner : {lo, glm::i64vec2(hi.x, lo.y), glm::i64vec2(lo.x, hi.y), hi}) {
          const int64_t e = detail::edgeFunction(a, b, corner);
          lowest = std::min(lowest, e), highest = std::max(highest, e);
        }
        // The triangle is e >= 0 (a degenerate one the line e == 0); the
        // open square is lowest < e < highest.
        if (highest <= 0 || (t.doubleArea == 0 && lowest >= 0)) {
          touches = false;
          break;
        }
      }
      if (touches) visit(static_cast<uint32_t>(x), static_cast<uint32_t>(y));
    }
}

template <class Visit>
void touchedTexels(const FixedTriangle& t, uint32_t size, Visit&& visit) {
  touchedTexels(t, size, [](uint32_t, uint32_t) { return false; }, visit);
}

}  // namespace sg::shadel
