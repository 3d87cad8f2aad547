#pragma once
// A procedural equirectangular sky written as a Radiance .hdr (stb_image_write),
// for environment-light tests and the effects bench: no HDR environment ships with the sample assets
// or Debian, so tests make their own.
#include <cstdint>
#include <filesystem>

namespace sg::bench {

// Rows from straight up (v = 0) down: a blue zenith (0.25, 0.45, 1.0) fading to a white horizon
// (1.2), a brown ground (0.3, 0.22, 0.15), and a sun disc of value `sun` 10 degrees
// across, 40 degrees up, towards +X -Z. Throws std::runtime_error when it cannot write.
void writeProceduralSky(const std::filesystem::path& file, uint32_t width = 256, uint32_t height = 128,
                        float sun = 500.0f);

}  // namespace sg::bench
