#pragma once
// Temporal flicker of frames rendered along a camera path.
//
// Frames F_0 .. F_{n-1} are sRGB-encoded 8-bit RGBA (alpha ignored), all of one size W x H, rendered at
// successive points of a path with sub-pixel motion. L(F)(p) is the linear luminance of pixel p:
//   L = 0.2126·R + 0.7152·G + 0.0722·B   (Rec. 709 weights of the sRGB-decoded values, so L is in [0, 1]).
// The temporal change of a sequence is the mean absolute frame-to-frame luminance change:
//   T(F) = 1 / ((n - 1)·W·H) · Σ_{t=0}^{n-2} Σ_p |L(F_{t+1})(p) - L(F_t)(p)|,   T = 0 when n < 2.
// A reference (ground-truth) sequence along the same path changes too, through the motion alone; what a test
// sequence changes beyond that is flicker:
//   excess = T(test) - T(reference)     (> 0: flickers more than the motion explains; can be < 0 when the
//                                        test is smoother than the reference, e.g. over-blurred)
//   ratio  = T(test) / T(reference)     (1 when T(test) = T(reference), including both 0; +inf when only
//                                        the reference is static)
#include <shadelgraph/image/png.hpp>

#include <span>

namespace sg::image {

// Throws std::invalid_argument if the frames differ in size or a pixel buffer does not match its size.
double temporalChange(std::span<const Rgba8Image> frames);

struct FlickerResult {
  double test = 0.0;       // T(test)
  double reference = 0.0;  // T(reference)
  double excess = 0.0;     // T(test) - T(reference)
  double ratio = 1.0;      // T(test) / T(reference)
};

// test and reference: the same number of frames of the same size, along the same path; throws
// std::invalid_argument otherwise.
FlickerResult flicker(std::span<const Rgba8Image> test, std::span<const Rgba8Image> reference);

}  // namespace sg::image
