#include "bench_path_quality.hpp"

#include <array>
#include <cmath>
#include <limits>

#include <shadelgraph/image/flicker.hpp>
#include <shadelgraph/image/flip.hpp>
#include <shadelgraph/image/metrics.hpp>

#include "bench_materials.hpp"

namespace sg::app {
namespace {

double mean(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x;
  return v.empty() ? 0.0 : sum / double(v.size());
}

// The samples of frames of one kind (fill or shade), null when there are none.
nlohmann::json ofKind(const std::vector<double>& samples, const std::vector<bool>& fill, bool wantFill, bool useMedian) {
  std::vector<double> picked;
  for (size_t i = 0; i < samples.size(); ++i)
    if (fill[i] == wantFill) picked.push_back(samples[i]);
  if (picked.empty()) return nullptr;
  return useMedian ? median(picked) : mean(picked);
}

}  // namespace

void PathQuality::add(const image::Rgba8Image& test, const image::Rgba8Image& reference, bool fillFrame) {
  flip_.push_back(image::flipLdr(reference, test).mean);
  psnr_.push_back(image::compareRgba8(reference.pixels, test.pixels).psnr);
  fill_.push_back(fillFrame);
  if (lastTest_) {
    changeTest_ += image::temporalChange(std::array{*lastTest_, test});
    changeReference_ += image::temporalChange(std::array{*lastReference_, reference});
    ++pairs_;
  }
  lastTest_ = test;
  lastReference_ = reference;
}

nlohmann::json PathQuality::json() const {
  const double t = pairs_ ? changeTest_ / pairs_ : 0.0, r = pairs_ ? changeReference_ / pairs_ : 0.0;
  // As image::flicker: 1 when both are 0, +inf (null in JSON) when only the reference is still.
  const double ratio = r > 0.0 ? t / r : (t > 0.0 ? std::numeric_limits<double>::infinity() : 1.0);
  return {{"flip_mean", mean(flip_)},
          {"flip_mean_shade_frames", ofKind(flip_, fill_, false, false)},
          {"flip_mean_fill_frames", ofKind(flip_, fill_, true, false)},
          {"psnr_median", median(psnr_)},
          {"psnr_median_shade_frames", ofKind(psnr_, fill_, false, true)},
          {"psnr_median_fill_frames", ofKind(psnr_, fill_, true, true)},
          {"flicker", t},
          {"flicker_reference", r},
          {"flicker_excess", t - r},
          {"flicker_ratio", ratio},
          {"flip_samples", flip_},
          {"psnr_samples", psnr_}};
}

}  // namespace sg::app
