// The CPU rasterizer behind the triangle-ID maps.
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/uv_rasterizer.hpp>

namespace sg::shadel {
namespace {

using TexelSet = std::set<std::pair<uint32_t, uint32_t>>;

TexelSet coverageOf(const FixedTriangle& t, uint32_t size) {
  TexelSet texels;
  coverage(t, size, [&](uint32_t x, uint32_t y) { texels.insert({x, y}); });
  return texels;
}

TexelSet touchedOf(const FixedTriangle& t, uint32_t size) {
  TexelSet texels;
  touchedTexels(t, size, [&](uint32_t x, uint32_t y) { texels.insert({x, y}); });
  return texels;
}

// Area of triangle ∩ square [x, x+1] x [y, y+1], by clipping (Sutherland-Hodgman).
double clippedArea(const FixedTriangle& t, uint32_t x, uint32_t y) {
  std::vector<glm::dvec2> polygon;
  for (const glm::i64vec2& v : t.v) polygon.push_back(glm::dvec2(v) / static_cast<double>(kSubTexels));
  const auto clip = [&](auto inside, auto intersect) {
    std::vector<glm::dvec2> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
      const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      if (inside(a)) out.push_back(a);
      if (inside(a) != inside(b)) out.push_back(intersect(a, b));
    }
    polygon = out;
  };
  const double x0 = x, x1 = x + 1.0, y0 = y, y1 = y + 1.0;
  const auto atX = [](double c) {
    return [c](glm::dvec2 a, glm::dvec2 b) { return a + (b - a) * ((c - a.x) / (b.x - a.x)); };
  };
  const auto atY = [](double c) {
    return [c](glm::dvec2 a, glm::dvec2 b) { return a + (b - a) * ((c - a.y) / (b.y - a.y)); };
  };
  clip([&](glm::dvec2 p) { return p.x >= x0; }, atX(x0));
  clip([&](glm::dvec2 p) { return p.x <= x1; }, atX(x1));
  clip([&](glm::dvec2 p) { return p.y >= y0; }, atY(y0));
  clip([&](glm::dvec2 p) { return p.y <= y1; }, atY(y1));
  double area = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return std::abs(area) * 0.5;
}

// An n x n grid of quads over a size x size map, interior vertices moved
// randomly (onto the half-texel lattice when `onCentres`, so many texel
// centres fall exactly on edges and vertices), each quad split along a
// random diagonal. Every texel centre must be covered exactly once.
void expectEveryCentreCoveredOnce(uint32_t size, int n, bool onCentres, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<glm::dvec2> vertices;
  const double step = static_cast<double>(size) / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      glm::dvec2 p(i * step, j * step);
      if (i > 0 && i < n && j > 0 && j < n) {
        // Small enough that every quad stays convex, so neither diagonal folds.
        std::uniform_real_distribution<double> jitter(-0.15 * step, 0.15 * step);
        p += glm::dvec2(jitter(rng), jitter(rng));
        if (onCentres) p = glm::floor(p) + 0.5;
      }
      vertices.push_back(p);
    }
  std::vector<int> count(size_t{size} * size, 0);
  const auto at = [n](int i, int j) { return static_cast<size_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 a = vertices[at(i, j)], b = vertices[at(i + 1, j)], c = vertices[at(i + 1, j + 1)],
                       d = vertices[at(i, j + 1)];
      const bool flip = rng() % 2;
      const FixedTriangle triangles[2] = {flip ? snapTriangle(a, b, d) : snapTriangle(a, b, c),
                                          flip ? snapTriangle(b, c, d) : snapTriangle(a, c, d)};
      for (const FixedTriangle& t : triangles)
        coverage(t, size, [&](uint32_t x, uint32_t y) { ++count[size_t{y} * size + x]; });
    }
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x)
      ASSERT_EQ(count[size_t{y} * size + x], 1) << "texel (" << x << ", " << y << ") seed " << seed;
}

TEST(UvRasterizer, SharedEdgesCoverEveryCentreExactlyOnce) {
  for (uint32_t seed = 0; seed < 20; ++seed) {
    expectEveryCentreCoveredOnce(64, 9, false, seed);
    expectEveryCentreCoveredOnce(32, 7, true, seed);
  }
}

TEST(UvRasterizer, AxisAlignedQuadFollowsTopLeftRule) {
  // The quad [0,16]², split along the diagonal from (0,0) to (16,16): centres
  // on the diagonal go to the triangle for which it is a left edge: the
  // upper-right one (y <= x in this y-down frame).
  const FixedTriangle upperRight = snapTriangle({0, 0}, {16, 0}, {16, 16});
  const FixedTriangle lowerLeft = snapTriangle({0, 0}, {16, 16}, {0, 16});
  const TexelSet a = coverageOf(upperRight, 16), b = coverageOf(lowerLeft, 16);
  EXPECT_EQ(a.size(), 136u);  // 16 * 17 / 2
  EXPECT_EQ(b.size(), 120u);
  for (uint32_t i = 0; i < 16; ++i) EXPECT_TRUE(a.count({i, i}));
  // Triangles reaching past the map are clipped to it.
  EXPECT_EQ(coverageOf(snapTriangle({-10, -10}, {60, -10}, {-10, 60}), 16).size(), 256u);
}

TEST(UvRasterizer, ConservativeIsEveryTexelWithAreaInside) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> position(-1.0, 17.0), offset(-1.5, 1.5), tiny(-0.02, 0.02);
  int compared = 0, ambiguous = 0;
  for (int i = 0; i < 3000; ++i) {
    glm::dvec2 a(position(rng), position(rng)), b, c;
    switch (i % 3) {
      case 0: b = {position(rng), position(rng)}, c = {position(rng), position(rng)}; break;  // large
      case 1: b = a + glm::dvec2(offset(rng), offset(rng)), c = a + glm::dvec2(offset(rng), offset(rng)); break;
      default: b = a + glm::dvec2(tiny(rng), tiny(rng)), c = a + glm::dvec2(tiny(rng), tiny(rng)); break;
    }
    if (i % 7 == 0) a = glm::floor(a), b = glm::floor(b);  // an edge or vertex on texel borders
    const FixedTriangle t = snapTriangle(a, b, c);
    if (t.doubleArea == 0) continue;
    const TexelSet touched = touchedOf(t, 16);
    for (uint32_t y = 0; y < 16; ++y)
      for (uint32_t x = 0; x < 16; ++x) {
        const double area = clippedArea(t, x, y);
        if (area > 0.0 && area < 1e-9) {
          ++ambiguous;
          continue;
        }
        ASSERT_EQ(touched.count({x, y}) == 1, area > 0.0) << "triangle " << i << " texel (" << x << ", " << y
                                                          << ") area " << area;
        ++compared;
      }
    for (const auto& texel : coverageOf(t, 16)) ASSERT_TRUE(touched.count(texel)) << "coverage within conservative";
  }
  EXPECT_GT(compared, 500000);
  EXPECT_LT(ambiguous, 50);
}

TEST(UvRasterizer, TinyAndDegenerateTriangles) {
  // Inside one texel, away from its centre: no coverage, one touched texel.
  const FixedTriangle tiny = snapTriangle({3.1, 4.1}, {3.2, 4.1}, {3.1, 4.3});
  EXPECT_TRUE(coverageOf(tiny, 8).empty());
  EXPECT_EQ(touchedOf(tiny, 8), (TexelSet{{3, 4}}));
  // A segment (zero area after snapping) across two texels touches both, covers none.
  const FixedTriangle segment = snapTriangle({2.5, 1.5}, {3.5, 1.5}, {3.0, 1.5});
  EXPECT_EQ(segment.doubleArea, 0);
  EXPECT_TRUE(coverageOf(segment, 8).empty());
  EXPECT_EQ(touchedOf(segment, 8), (TexelSet{{2, 1}, {3, 1}}));
  // Lying exactly on a texel border it has no area in either texel.
  EXPECT_TRUE(touchedOf(snapTriangle({2, 1}, {4, 1}, {3, 1}), 8).empty());
  // Distances.
  EXPECT_DOUBLE_EQ(distanceToTriangle(tiny, {3.15, 4.15}), 0.0);
  EXPECT_NEAR(distanceToTriangle(tiny, {3.1, 5.1}), 0.8, 1e-2);
}

}  // namespace
}  // namespace sg::shadel
