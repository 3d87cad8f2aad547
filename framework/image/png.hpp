#pragma once
// PNG files through stb_image_write / stb_image.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace sg::image {

struct Rgba8Image {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> pixels;  // rows top to bottom, 4 bytes a pixel
};

// Creates parent directories; throws std::runtime_error naming the path on failure.
void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const uint8_t* rgba);
Rgba8Image readPng(const std::filesystem::path& path);

}  // namespace sg::image
