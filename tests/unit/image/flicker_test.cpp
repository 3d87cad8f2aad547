// Temporal flicker tests; expected values are exact by construction (flat frames, known luminance).
#include <shadelgraph/image/flicker.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace {

using sg::image::Rgba8Image;

Rgba8Image flat(uint32_t w, uint32_t h, uint8_t v) {
  Rgba8Image img{w, h, std::vector<uint8_t>(size_t(w) * h * 4, v)};
  return img;
}

// A bright bar on a dark ground moving right by a quarter pixel a frame, its edges anti-aliased: what a
// reference renderer would produce along a path with sub-pixel motion.
std::vector<Rgba8Image> movingBar(size_t frames) {
  std::vector<Rgba8Image> seq;
  for (size_t t = 0; t < frames; ++t) {
    Rgba8Image img = flat(64, 16, 20);
    const double left = 10.0 + 0.25 * double(t), right = left + 12.0;
    for (uint32_t x = 0; x < 64; ++x) {
      const double cover = std::max(0.0, std::min(double(x) + 1.0, right) - std::max(double(x), left));
      const auto v = uint8_t(20.0 + 200.0 * std::min(cover, 1.0) + 0.5);
      for (uint32_t y = 0; y < 16; ++y)
        for (size_t c = 0; c < 3; ++c) img.pixels[4 * (size_t(y) * 64 + x) + c] = v;
    }
    seq.push_back(std::move(img));
  }
  return seq;
}

TEST(Flicker, StaticSequenceHasNoChange) {
  const std::vector<Rgba8Image> seq(5, flat(8, 6, 77));
  EXPECT_EQ(sg::image::temporalChange(seq), 0.0);
  EXPECT_EQ(sg::image::temporalChange(std::vector<Rgba8Image>{flat(8, 6, 77)}), 0.0);
  EXPECT_EQ(sg::image::temporalChange(std::vector<Rgba8Image>{}), 0.0);
}

TEST(Flicker, AlternatingBlackAndWhiteIsOne) {
  std::vector<Rgba8Image> seq;
  for (int t = 0; t < 6; ++t) seq.push_back(flat(8, 6, t % 2 ? 255 : 0));
  EXPECT_NEAR(sg::image::temporalChange(seq), 1.0, 1e-6);
}

TEST(Flicker, MidGreyStepIsItsLinearLuminance) {
  // sRGB 128 decodes to ((128/255 + 0.055) / 1.055)^2.4 = 0.215861; grey has L equal to that.
  const std::vector<Rgba8Image> seq{flat(4, 4, 0), flat(4, 4, 128), flat(4, 4, 128)};
  EXPECT_NEAR(sg::image::temporalChange(seq), 0.215861 / 2, 1e-6);
}

TEST(Flicker, SequenceEqualToReferenceHasNoExcess) {
  const std::vector<Rgba8Image> ref = movingBar(12);
  const sg::image::FlickerResult r = sg::image::flicker(ref, ref);
  EXPECT_GT(r.reference, 0.0);  // the motion itself changes pixels
  EXPECT_EQ(r.test, r.reference);
  EXPECT_EQ(r.excess, 0.0);
  EXPECT_EQ(r.ratio, 1.0);
}

TEST(Flicker, NoiseInTheTestIsPositiveExcess) {
  const std::vector<Rgba8Image> ref = movingBar(12);
  std::vector<Rgba8Image> test = ref;
  uint32_t s = 7;
  for (Rgba8Image& f : test)
    for (size_t i = 0; i < f.pixels.size(); i += 4) {
      s = 1664525u * s + 1013904223u;
      const int n = int((s >> 24) % 17) - 8;  // per-frame noise in [-8, 8], grey
      for (size_t c = 0; c < 3; ++c) f.pixels[i + c] = uint8_t(std::clamp(int(f.pixels[i + c]) + n, 0, 255));
    }
  const sg::image::FlickerResult r = sg::image::flicker(test, ref);
  EXPECT_GT(r.excess, 0.0);
  EXPECT_GT(r.ratio, 1.0);
  EXPECT_DOUBLE_EQ(r.excess, r.test - r.reference);
  EXPECT_DOUBLE_EQ(r.ratio, r.test / r.reference);
}

TEST(Flicker, StaticReference) {
  const std::vector<Rgba8Image> still(3, flat(4, 4, 50));
  EXPECT_EQ(sg::image::flicker(still, still).ratio, 1.0);
  const std::vector<Rgba8Image> blink{flat(4, 4, 50), flat(4, 4, 60), flat(4, 4, 50)};
  EXPECT_TRUE(std::isinf(sg::image::flicker(blink, still).ratio));
}

TEST(Flicker, RejectsMismatchedSequences) {
  const std::vector<Rgba8Image> two(2, flat(4, 4, 0)), three(3, flat(4, 4, 0));
  EXPECT_THROW(sg::image::flicker(two, three), std::invalid_argument);
  const std::vector<Rgba8Image> mixed{flat(4, 4, 0), flat(4, 5, 0)};
  EXPECT_THROW(sg::image::temporalChange(mixed), std::invalid_argument);
}

}  // namespace
