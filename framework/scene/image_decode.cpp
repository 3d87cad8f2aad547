#include <climits>
#include <memory>
#include <stdexcept>
#include <string>

#include <stb_image.h>

#include <shadelgraph/scene/image_decode.hpp>

namespace sg::scene {
namespace {

// stb_image's reason for the last failure; it may have none (NULL), and a
// reason left over from an earlier probe would be stale, so say which step failed.
std::runtime_error decodeError(const char* step) {
  const char* reason = stbi_failure_reason();
  return std::runtime_error(std::string(step) + (reason ? std::string(": ") + reason : std::string()));
}

}  // namespace

DecodedImage decodeImage(std::span<const uint8_t> bytes, bool headerOnly) {
  if (bytes.empty()) throw std::runtime_error("no image data");
  if (bytes.size() > static_cast<size_t>(INT_MAX)) throw std::runtime_error("image larger than 2 GiB");
  const int length = static_cast<int>(bytes.size());
  int width = 0, height = 0, channels = 0;
  DecodedImage image;
  if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &channels))
    throw decodeError("cannot read the image header");
  // The header is checked before decoding: a 100-byte file may claim
  // 100000 x 100000 pixels, and stb_image would allocate what it claims.
  if (width > kMaxImageSide || height > kMaxImageSide)
    throw std::runtime_error("image is " + std::to_string(width) + "x" + std::to_string(height) + ", more than " +
                             std::to_string(kMaxImageSide) + " pixels on a side");
  if (!headerOnly) {
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), length, &width, &height, &channels, STBI_rgb_alpha), stbi_image_free);
    if (!pixels) throw decodeError("cannot decode the image");
    image.rgba.assign(pixels.get(), pixels.get() + static_cast<size_t>(width) * static_cast<size_t>(height) * 4);
  }
  image.width = static_cast<uint32_t>(width);
  image.height = static_cast<uint32_t>(height);
  return image;
}

}  // namespace sg::scene
