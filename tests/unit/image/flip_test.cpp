// ꟻLIP (LDR) tests. Which numbers are independent of flipLdr:
//  * FlatColours*: a flat field has no features (every detector kernel sums to zero) and the CSF filters
//    (unit sum, clamped borders) leave it unchanged, so ꟻLIP reduces to the remapped Hunt-adjusted HyAB
//    distance of the two colours. handColorError() below recomputes that in double precision straight from
//    the paper's formulas, sharing no code with flipLdr; black vs white is also checked against the value
//    worked out by hand (HyAB = 100, cmax = 203.3^0.7 = 41.276 -> 0.95 + 0.05·(100^0.7 - 0.4·cmax) /
//    (0.6·cmax) = 0.96738).
//  * MatchesReferenceImplementation: the numbers were produced by a numpy/scipy port of NVIDIA's Python
//    reference (flip_api.py, compute_ldrflip: full 2D kernels, correlation with replicated borders) on the
//    images that pattern(), noisy() and shifted() build here (the port builds the same pixels).
//  * The rest are properties: zero for identical images, monotonic in the size of a difference, symmetric,
//    local support of a one-pixel change.
#include <shadelgraph/image/flip.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace {

using sg::image::FlipResult;
using sg::image::Rgba8Image;

Rgba8Image flat(uint32_t w, uint32_t h, uint8_t r, uint8_t g, uint8_t b) {
  Rgba8Image img{w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    img.pixels[4 * i] = r;
    img.pixels[4 * i + 1] = g;
    img.pixels[4 * i + 2] = b;
    img.pixels[4 * i + 3] = 255;
  }
  return img;
}

uint8_t* at(Rgba8Image& img, uint32_t x, uint32_t y) { return &img.pixels[4 * (size_t(y) * img.width + x)]; }

// 64x48: red ramp along x, green ramp along y, a blue disk of radius 12 on blue 40.
Rgba8Image pattern() {
  Rgba8Image img = flat(64, 48, 0, 0, 0);
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      uint8_t* p = at(img, x, y);
      p[0] = uint8_t((x * 4) & 255);
      p[1] = uint8_t((y * 5) & 255);
      const int dx = int(x) - 32, dy = int(y) - 24;
      p[2] = dx * dx + dy * dy < 144 ? 255 : 40;
    }
  return img;
}

// Adds noise in [-20, 20] from a 32-bit LCG, pixel by pixel, R, G, B.
Rgba8Image noisy(const Rgba8Image& src) {
  Rgba8Image img = src;
  uint32_t s = 12345;
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
    for (size_t c = 0; c < 3; ++c) {
      s = 1664525u * s + 1013904223u;
      const int n = int((s >> 24) % 41) - 20;
      img.pixels[4 * i + c] = uint8_t(std::clamp(int(img.pixels[4 * i + c]) + n, 0, 255));
    }
  return img;
}

// Shifted one pixel right, the first column repeated.
Rgba8Image shifted(const Rgba8Image& src) {
  Rgba8Image img = src;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 1; x < img.width; ++x)
      std::copy_n(&src.pixels[4 * (size_t(y) * src.width + x - 1)], 4, at(img, x, y));
  return img;
}

// --- The colour error of two flat colours, by hand, in double precision -------------------------------
struct V3 {
  double x, y, z;
};

double decode(uint8_t v) {
  const double s = v / 255.0;
  return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

V3 huntLab(V3 rgb) {
  // Linear sRGB to XYZ (the matrix from the sRGB primaries and D65 white), CIELAB against the display's white
  // (the matrix applied to (1, 1, 1)), Hunt: a, b scaled by L/100.
  constexpr double m[3][3] = {{0.4123908, 0.3575843, 0.1804808},
                              {0.2126390, 0.7151687, 0.0721923},
                              {0.0193308, 0.1191948, 0.9505322}};
  const V3 xyz{m[0][0] * rgb.x + m[0][1] * rgb.y + m[0][2] * rgb.z, m[1][0] * rgb.x + m[1][1] * rgb.y + m[1][2] * rgb.z,
               m[2][0] * rgb.x + m[2][1] * rgb.y + m[2][2] * rgb.z};
  const V3 white{m[0][0] + m[0][1] + m[0][2], m[1][0] + m[1][1] + m[1][2], m[2][0] + m[2][1] + m[2][2]};
  auto f = [](double t) { return t > std::pow(6.0 / 29.0, 3) ? std::cbrt(t) : t / (3 * std::pow(6.0 / 29.0, 2)) + 4.0 / 29.0; };
  const double fx = f(xyz.x / white.x), fy = f(xyz.y / white.y), fz = f(xyz.z / white.z);
  const double L = 116 * fy - 16;
  return {L, L / 100 * 500 * (fx - fy), L / 100 * 200 * (fy - fz)};
}

double hyab(V3 a, V3 b) { return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z); }

double handColorError(const uint8_t a[3], const uint8_t b[3]) {
  const double cmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), 0.7);
  const double e = std::pow(hyab(huntLab({decode(a[0]), decode(a[1]), decode(a[2])}),
                                 huntLab({decode(b[0]), decode(b[1]), decode(b[2])})),
                            0.7);
  return e < 0.4 * cmax ? 0.95 / (0.4 * cmax) * e : 0.95 + (e - 0.4 * cmax) / (0.6 * cmax) * 0.05;
}

TEST(Flip, IdenticalImagesHaveNoError) {
  const Rgba8Image a = noisy(pattern());
  const FlipResult r = sg::image::flipLdr(a, a);
  ASSERT_EQ(r.errorMap.size(), size_t(64) * 48);
  EXPECT_EQ(r.width, 64u);
  EXPECT_EQ(r.height, 48u);
  EXPECT_EQ(r.mean, 0.0);
  EXPECT_EQ(r.max, 0.0);
  EXPECT_EQ(r.median, 0.0);
  EXPECT_EQ(r.weightedMedian, 0.0);
}

TEST(Flip, FlatBlackVersusWhiteMatchesHandValue) {
  const Rgba8Image black = flat(32, 24, 0, 0, 0), white = flat(32, 24, 255, 255, 255);
  const FlipResult r = sg::image::flipLdr(black, white);
  const uint8_t k[3] = {0, 0, 0}, w[3] = {255, 255, 255};
  EXPECT_NEAR(handColorError(k, w), 0.96738, 1e-5);  // worked out by hand, see the top
  EXPECT_NEAR(r.mean, handColorError(k, w), 5e-6);
  EXPECT_NEAR(r.max, handColorError(k, w), 5e-6);
  for (float e : r.errorMap) EXPECT_NEAR(e, r.mean, 1e-5);
}

TEST(Flip, FlatColoursMatchTheColourErrorComputedByHand) {
  const uint8_t pairs[][2][3] = {{{128, 128, 128}, {140, 140, 140}}, {{255, 0, 0}, {0, 255, 0}},
                                 {{30, 60, 90}, {32, 58, 95}},       {{200, 180, 20}, {20, 180, 200}},
                                 {{10, 10, 10}, {12, 10, 10}},       {{90, 200, 120}, {90, 200, 120}}};
  for (const auto& pair : pairs) {
    const Rgba8Image a = flat(24, 16, pair[0][0], pair[0][1], pair[0][2]);
    const Rgba8Image b = flat(24, 16, pair[1][0], pair[1][1], pair[1][2]);
    const FlipResult r = sg::image::flipLdr(a, b);
    const double expected = handColorError(pair[0], pair[1]);
    EXPECT_NEAR(r.mean, expected, 5e-6) << int(pair[0][0]) << "," << int(pair[0][1]) << "," << int(pair[0][2]);
    EXPECT_NEAR(r.max, expected, 5e-6);
  }
  // The reference port gives 0.1691144 for grey 128 vs 140 and 0.9866632 for red vs green.
  EXPECT_NEAR(sg::image::flipLdr(flat(8, 8, 128, 128, 128), flat(8, 8, 140, 140, 140)).mean, 0.1691144, 1e-5);
  EXPECT_NEAR(sg::image::flipLdr(flat(8, 8, 255, 0, 0), flat(8, 8, 0, 255, 0)).mean, 0.9866632, 1e-5);
}

TEST(Flip, MatchesReferenceImplementation) {
  const Rgba8Image ref = pattern();
  struct Expected {
    const char* name;
    Rgba8Image test;
    double mean, max, weightedMedian, median, px00, px3224, px6347, px1030;
  };
  const Expected cases[] = {
      {"noise", noisy(ref), 0.1137601, 0.3604127, 0.1251533, 0.1103156, 0.0755055, 0.1387080, 0.3604127, 0.0800574},
      {"shift", shifted(ref), 0.0991414, 0.4305521, 0.1064763, 0.0897214, 0.0109211, 0.0541441, 0.0935147, 0.0319644},
  };
  for (const Expected& c : cases) {
    const FlipResult r = sg::image::flipLdr(ref, c.test);
    auto px = [&](uint32_t x, uint32_t y) { return double(r.errorMap[size_t(y) * r.width + x]); };
    constexpr double tol = 1e-5;
    EXPECT_NEAR(r.mean, c.mean, tol) << c.name;
    EXPECT_NEAR(r.max, c.max, tol) << c.name;
    EXPECT_NEAR(r.weightedMedian, c.weightedMedian, tol) << c.name;
    EXPECT_NEAR(r.median, c.median, tol) << c.name;
    EXPECT_NEAR(px(0, 0), c.px00, tol) << c.name;
    EXPECT_NEAR(px(32, 24), c.px3224, tol) << c.name;
    EXPECT_NEAR(px(63, 47), c.px6347, tol) << c.name;
    EXPECT_NEAR(px(10, 30), c.px1030, tol) << c.name;
  }
}

TEST(Flip, ErrorGrowsWithTheDifference) {
  const Rgba8Image ref = flat(96, 64, 100, 110, 120);
  double previous = 0.0;
  for (int d : {2, 4, 8, 16, 32, 64, 128}) {
    Rgba8Image test = ref;
    for (uint32_t y = 20; y < 44; ++y)
      for (uint32_t x = 30; x < 66; ++x) at(test, x, y)[1] = uint8_t(110 + d);
    const double mean = sg::image::flipLdr(ref, test).mean;
    EXPECT_GT(mean, previous) << "d=" << d;
    previous = mean;
  }
}

TEST(Flip, IsSymmetric) {
  const Rgba8Image a = pattern(), b = noisy(a);
  const FlipResult ab = sg::image::flipLdr(a, b), ba = sg::image::flipLdr(b, a);
  EXPECT_NEAR(ab.mean, ba.mean, 1e-6);
  for (size_t i = 0; i < ab.errorMap.size(); ++i) ASSERT_NEAR(ab.errorMap[i], ba.errorMap[i], 1e-5) << i;
}

TEST(Flip, OnePixelChangeStaysLocal) {
  const Rgba8Image ref = flat(120, 100, 90, 90, 90);
  Rgba8Image test = ref;
  const uint32_t cx = 60, cy = 50;
  std::fill_n(at(test, cx, cy), 3, uint8_t(250));
  const FlipResult r = sg::image::flipLdr(ref, test);
  // At 67 ppd the CSF radius is ceil(3·sqrt(0.04 / (2 pi²))·67.02) = 10 px and the feature radius 9 px.
  const int reach = 10;
  double inside = 0.0;
  for (uint32_t y = 0; y < r.height; ++y)
    for (uint32_t x = 0; x < r.width; ++x) {
      const float e = r.errorMap[size_t(y) * r.width + x];
      if (std::max(std::abs(int(x) - int(cx)), std::abs(int(y) - int(cy))) > reach)
        ASSERT_EQ(e, 0.0f) << x << "," << y;
      else
        inside = std::max(inside, double(e));
    }
  EXPECT_GT(r.errorMap[size_t(cy) * r.width + cx], 0.1f);
  EXPECT_EQ(inside, r.max);
  EXPECT_LT(r.mean, r.max / 50);
}

TEST(Flip, PixelsPerDegreeChangesTheResult) {
  const Rgba8Image a = pattern(), b = noisy(a);
  // Seen from further away (more pixels per degree) pixel noise is filtered more.
  EXPECT_LT(sg::image::flipLdr(a, b, 134.0).mean, sg::image::flipLdr(a, b, 33.5).mean);
}

TEST(Flip, RejectsMismatchedImages) {
  EXPECT_THROW(sg::image::flipLdr(flat(4, 4, 0, 0, 0), flat(4, 5, 0, 0, 0)), std::invalid_argument);
  Rgba8Image broken = flat(4, 4, 0, 0, 0);
  broken.pixels.pop_back();
  EXPECT_THROW(sg::image::flipLdr(broken, flat(4, 4, 0, 0, 0)), std::invalid_argument);
}

TEST(Flip, HeatmapUsesMagma) {
  FlipResult r;
  r.width = 3;
  r.height = 1;
  r.errorMap = {0.0f, 0.5f, 1.0f};
  const Rgba8Image h = sg::image::flipHeatmap(r);
  ASSERT_EQ(h.pixels.size(), 12u);
  // magma[0] = (0.001462, 0.000466, 0.013866), magma[128] = (0.716387, 0.214982, 0.475290),
  // magma[255] = (0.987053, 0.991438, 0.749504), times 255 and rounded.
  const uint8_t expected[12] = {0, 0, 4, 255, 183, 55, 121, 255, 252, 253, 191, 255};
  for (size_t i = 0; i < 12; ++i) EXPECT_EQ(h.pixels[i], expected[i]) << i;
}

TEST(Flip, Timing640x360) {
  Rgba8Image a = flat(640, 360, 0, 0, 0);
  for (uint32_t y = 0; y < 360; ++y)
    for (uint32_t x = 0; x < 640; ++x) {
      uint8_t* p = at(a, x, y);
      p[0] = uint8_t(x * 255 / 639);
      p[1] = uint8_t(y * 255 / 359);
      p[2] = uint8_t(((x / 16 + y / 16) % 2) * 200);
    }
  const Rgba8Image b = noisy(a);
  // Best of five: the machine's cores are shared.
  FlipResult r;
  double ms = 1e30;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    r = sg::image::flipLdr(a, b);
    ms = std::min(ms, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("flipLdr 640x360: %.1f ms, best of 5 (mean error %.4f)\n", ms, r.mean);
  EXPECT_GT(r.mean, 0.0);
}

}  // namespace
