#include "shade_space_adjuster.hpp"

#include <algorithm>
#include <cmath>

namespace sg::plugins {

float ShadeSpaceAdjuster::update(const ShadeSpaceCounters& c) {
  if (c.chunksCapacity == 0) return bias_;
  const double use = double(c.chunksRequested) / double(c.chunksCapacity);
  // One level of bias halves the shadel density in each direction: a quarter
  // of the shadels. So the bias that brings `use` to `target` is
  // frameBias + log4(use / target).
  auto biasFor = [&](float fraction) {
    return c.bias + float(0.5 * std::log2(std::max(use, 1e-9) / double(fraction)));
  };
  if (use > double(options_.high)) {
    bias_ = std::max(bias_, biasFor(options_.target));
  } else if (c.overflowChunks > 0) {
    // Overflow below the high watermark: one hashed partition filled before
    // the others. Step coarser until none does.
    bias_ = std::max(bias_, c.bias + options_.overflowStep);
  } else if (use < double(options_.low) && c.chunksRequested > 0) {
    // Relax towards the target, a step at a time, never below what that frame
    // says would reach the target.
    bias_ = std::max({bias_ - options_.relaxStep, biasFor(options_.target), options_.minBias});
  }
  bias_ = std::clamp(bias_, options_.minBias, options_.maxBias);
  return bias_;
}

}  // namespace sg::plugins
