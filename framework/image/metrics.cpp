#include <shadelgraph/image/metrics.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace sg::image {

ImageDifference compareRgba8(std::span<const uint8_t> a, std::span<const uint8_t> b) {
  if (a.size() != b.size() || a.size() % 4 != 0) throw std::invalid_argument("compareRgba8: images differ in size");
  ImageDifference d;
  double squared = 0.0, absolute = 0.0;
  size_t above = 0;
  const size_t pixels = a.size() / 4;
  for (size_t i = 0; i < a.size(); i += 4) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int diff = std::abs(int(a[i + c]) - int(b[i + c]));
      squared += double(diff) * diff;
      absolute += diff;
      worst = std::max(worst, diff);
    }
    d.maxAbs = std::max(d.maxAbs, worst);
    above += worst > 8;
  }
  const double mse = squared / double(pixels * 3);
  d.psnr = mse == 0.0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  d.meanAbs = absolute / double(pixels * 3);
  d.fractionAbove8 = double(above) / double(pixels);
  return d;
}

}  // namespace sg::image
