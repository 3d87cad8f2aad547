#pragma once
// Copies an image back to the host for tests, PNG output and metrics.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;
class MemoryAllocator;
class Image;

struct HostImage {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba8;  // tightly packed rows
  const uint8_t* pixel(uint32_t x, uint32_t y) const { return &rgba8[(size_t(y) * width + x) * 4]; }
};

// The image must be an 8-bit RGBA/BGRA colour image currently in `layout`;
// it is left in that layout. BGRA is swizzled to RGBA.
HostImage readImage(Context& context, MemoryAllocator& memory, const Image& image, VkImageLayout layout);

}  // namespace sg::gpu
