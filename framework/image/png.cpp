#include <shadelgraph/image/png.hpp>

#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

namespace sg::image {

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const uint8_t* rgba) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  if (!stbi_write_png(path.c_str(), int(width), int(height), 4, rgba, int(width * 4)))
    throw std::runtime_error(path.string() + ": cannot write PNG");
}

Rgba8Image readPng(const std::filesystem::path& path) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) throw std::runtime_error(path.string() + ": cannot read PNG (" + stbi_failure_reason() + ")");
  Rgba8Image image{uint32_t(w), uint32_t(h), std::vector<uint8_t>(data, data + size_t(w) * h * 4)};
  stbi_image_free(data);
  return image;
}

}  // namespace sg::image
