#pragma once
// What a sequence of frames along a path gets wrong against its reference
// sequence (the same poses at 16 spp), accumulated frame by frame so no
// sequence is kept: ꟻLIP and PSNR of each frame against the reference of the
// same frame, split by shade and fill frames, and flicker (image/flicker.hpp)
// from consecutive pairs — T over n frames is the mean of its n − 1 pairs' T.
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/image/png.hpp>

namespace sg::app {

class PathQuality {
 public:
  // Frames in path order; `fillFrame`: a raster frame that was not a shade frame.
  void add(const image::Rgba8Image& test, const image::Rgba8Image& reference, bool fillFrame);
  // flip_mean, psnr_median (also _shade_frames / _fill_frames: null when there
  // were none), flicker, flicker_reference, flicker_excess, flicker_ratio, and
  // flip_samples, psnr_samples in path order.
  nlohmann::json json() const;
  const std::vector<double>& flipSamples() const { return flip_; }

 private:
  std::vector<double> flip_, psnr_;
  std::vector<bool> fill_;
  std::optional<image::Rgba8Image> lastTest_, lastReference_;
  double changeTest_ = 0.0, changeReference_ = 0.0;
  int pairs_ = 0;
};

}  // namespace sg::app
