#pragma once

#include <cstdint>
#include <string_view>

namespace sg::graph {

// Image formats the graph can declare; the gpu layer maps them 1:1 to VkFormat.
enum class Format : uint8_t {
  Undefined,
  R8Unorm,
  RGBA8Unorm,
  RGBA8Srgb,
  BGRA8Unorm,
  R16F,
  RG16F,
  RGBA16F,
  R32F,
  RG32F,
  RGBA32F,
  R32Uint,
  RG32Uint,
  RGBA32Uint,
  D32F,
  D24S8,
};

// Inline: validate() asks it for every image access.
constexpr bool isDepth(Format format) { return format == Format::D32F || format == Format::D24S8; }
constexpr bool hasStencil(Format format) { return format == Format::D24S8; }
// Size of one texel in bytes; 0 for Undefined.
uint32_t bytesPerTexel(Format format);
std::string_view toString(Format format);

}  // namespace sg::graph
