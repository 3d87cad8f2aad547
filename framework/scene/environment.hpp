#pragma once
// A scene's environment light: an equirectangular HDR image (Radiance .hdr,
// read with stb_image) that image-based lighting prefilters once and samples.
// Without one the frame keeps the analytic sky and holds no environment pass.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sg::scene {

struct Environment {
  std::filesystem::path file;  // empty: no environment (the analytic sky)
  uint32_t width = 0, height = 0;
  // Linear RGBA, rows from the top (+Y, straight up) down; column 0 looks along -Z
  // and columns turn towards +X (u = atan2(x, -z) / 2pi + 1/2, v = acos(y) / pi).
  std::vector<float> rgba;
  float intensity = 1.0f;  // luminance (cd/m^2) of a pixel value of 1

  bool present() const { return !file.empty(); }
};

// Largest side of an environment image: the prefilter reads every texel once.
inline constexpr int kMaxEnvironmentSide = 8192;

// Reads a Radiance .hdr; throws SceneError("<file>: <what>") for a file that is
// missing, not a Radiance image, or malformed, and for pixels that are not finite.
Environment loadEnvironment(const std::filesystem::path& file, float intensity);

}  // namespace sg::scene
