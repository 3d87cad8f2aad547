#pragma once
// Image error metrics over 8-bit RGB (alpha ignored).
#include <cstdint>
#include <span>

namespace sg::image {

struct ImageDifference {
  double psnr = 0.0;    // dB over RGB; +infinity for identical images
  double meanAbs = 0.0;  // mean absolute difference per channel, in 1/255 units
  int maxAbs = 0;        // largest absolute channel difference
  double fractionAbove8 = 0.0;  // pixels whose largest channel difference exceeds 8/255
};

// a and b: RGBA8, the same number of pixels.
ImageDifference compareRgba8(std::span<const uint8_t> a, std::span<const uint8_t> b);

}  // namespace sg::image
