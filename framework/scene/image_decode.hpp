#pragma once
// Image decoding with stb_image (PNG, JPEG, BMP, GIF, TGA, ...).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sg::scene {

struct DecodedImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;  // RGBA8, rows top to bottom; empty when only the header was read
};

// Largest width or height accepted (Vulkan's usual maxImageDimension2D):
// checked from the header before any pixel is allocated.
inline constexpr int kMaxImageSide = 16384;

// Decodes to RGBA8 (grey and RGB get opaque alpha, 16-bit channels are
// reduced to 8). headerOnly: reads only the size, without decoding pixels.
// Throws std::runtime_error with stb_image's reason when the bytes are not an
// image it can read.
DecodedImage decodeImage(std::span<const uint8_t> bytes, bool headerOnly = false);

}  // namespace sg::scene
