#include <shadelgraph/image/flicker.hpp>

#include <shadelgraph/image/flip.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace sg::image {
namespace {

void luminance(const Rgba8Image& frame, std::vector<double>& out) {
  out.resize(size_t(frame.width) * frame.height);
  for (size_t i = 0; i < out.size(); ++i) {
    const uint8_t* p = &frame.pixels[4 * i];
    out[i] = 0.2126 * double(srgbToLinear(p[0])) + 0.7152 * double(srgbToLinear(p[1])) +
             0.0722 * double(srgbToLinear(p[2]));
  }
}

}  // namespace

double temporalChange(std::span<const Rgba8Image> frames) {
  for (const Rgba8Image& f : frames) {
    if (f.pixels.size() != size_t(f.width) * f.height * 4)
      throw std::invalid_argument("temporalChange: a frame's pixel buffer does not match its size");
    if (f.width != frames[0].width || f.height != frames[0].height)
      throw std::invalid_argument("temporalChange: frames differ in size");
  }
  if (frames.size() < 2 || frames[0].pixels.empty()) return 0.0;
  std::vector<double> previous, current;
  luminance(frames[0], previous);
  double sum = 0.0;
  for (size_t t = 1; t < frames.size(); ++t) {
    luminance(frames[t], current);
    for (size_t i = 0; i < current.size(); ++i) sum += std::abs(current[i] - previous[i]);
    previous.swap(current);
  }
  return sum / (double(frames.size() - 1) * double(previous.size()));
}

FlickerResult flicker(std::span<const Rgba8Image> test, std::span<const Rgba8Image> reference) {
  if (test.size() != reference.size()) throw std::invalid_argument("flicker: sequences differ in length");
  if (!test.empty() && (test[0].width != reference[0].width || test[0].height != reference[0].height))
    throw std::invalid_argument("flicker: sequences differ in frame size");
  FlickerResult r;
  r.test = temporalChange(test);
  r.reference = temporalChange(reference);
  r.excess = r.test - r.reference;
  r.ratio = r.reference > 0.0 ? r.test / r.reference
                              : (r.test == 0.0 ? 1.0 : std::numeric_limits<double>::infinity());
  return r;
}

}  // namespace sg::image
