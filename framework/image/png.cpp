#include <shadelgraph/image/png.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <stb_image.h>
#include <stb_image_write.h>

namespace sg::image {

namespace {

// stb hands the encoded PNG over in pieces; a failed fwrite is remembered.
void appendToFile(void* context, void* data, int size) {
  auto* file = static_cast<FILE*>(context);
  if (size > 0) std::fwrite(data, 1, size_t(size), file);
}

}  // namespace

void writePng(const std::filesystem::path& path, uint32_t width, uint32_t height, const uint8_t* rgba) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  auto fail = [&](const char* reason) { throw std::runtime_error(path.string() + ": cannot write PNG (" + reason + ")"); };
  errno = 0;
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) fail(std::strerror(errno));
  const int encoded = stbi_write_png_to_func(appendToFile, file, int(width), int(height), 4, rgba, int(width * 4));
  // A full disk shows only when the buffered bytes are written: at fflush or fclose.
  const bool written = encoded && std::fflush(file) == 0 && !std::ferror(file);
  const int error = errno;
  const bool closed = std::fclose(file) == 0;
  if (!encoded) fail("encoding failed");
  if (!written || !closed) fail(std::strerror(error ? error : errno ? errno : EIO));
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
