#pragma once

#include <shadelgraph/graph/format.hpp>
#include <shadelgraph/graph/queue.hpp>
#include <shadelgraph/graph/usage.hpp>

#include <cstdint>
#include <string_view>

namespace sg::graph {

// An image size: absolute texels, or a scale of the output extent given at compile.
struct Size {
  enum class Mode : uint8_t { Absolute, Relative };
  Mode mode = Mode::Relative;
  uint32_t width = 0;  // Absolute
  uint32_t height = 0;
  float scaleX = 1.0f;  // Relative
  float scaleY = 1.0f;

  static constexpr Size absolute(uint32_t w, uint32_t h) { return {Mode::Absolute, w, h, 0.0f, 0.0f}; }
  static constexpr Size relative(float scale) { return {Mode::Relative, 0, 0, scale, scale}; }
  static constexpr Size relative(float sx, float sy) { return {Mode::Relative, 0, 0, sx, sy}; }
  friend bool operator==(const Size&, const Size&) = default;
};

struct ImageDesc {
  Format format = Format::RGBA8Unorm;
  Size size = Size::relative(1.0f);
  uint32_t depth = 1;  // > 1 for a 3D image
  uint32_t layers = 1;
  uint32_t mipLevels = 1;
  uint32_t samples = 1;
  friend bool operator==(const ImageDesc&, const ImageDesc&) = default;
};

struct BufferDesc {
  uint64_t size = 0;  // bytes
  friend bool operator==(const BufferDesc&, const BufferDesc&) = default;
};

enum class ResourceKind : uint8_t {
  TransientImage,   // lives within the frame; may alias memory
  TransientBuffer,  // lives within the frame; may alias memory
  Imported,         // owned outside the graph (output image, readback buffers)
  Persistent,       // owned by a plugin across frames; contents survive
  History,          // the previous frame's version of a persistent resource; read-only
};

enum class ResourceType : uint8_t { Image, Buffer };

constexpr bool isTransient(ResourceKind kind) {
  return kind == ResourceKind::TransientImage || kind == ResourceKind::TransientBuffer;
}

// An image description with the size resolved against the output extent.
struct ResolvedImageDesc {
  Format format = Format::Undefined;
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t depth = 1;
  uint32_t layers = 1;
  uint32_t mipLevels = 1;
  uint32_t samples = 1;
  friend bool operator==(const ResolvedImageDesc&, const ResolvedImageDesc&) = default;
};

// Everything the gpu layer needs to create the Vulkan object of a resource
// (and to query its memory requirements).
struct ResourceDesc {
  ResourceType type = ResourceType::Image;
  ResolvedImageDesc image;  // type == Image
  uint64_t bufferSize = 0;  // type == Buffer
  ImageUsage imageUsage = ImageUsage::None;
  BufferUsage bufferUsage = BufferUsage::None;
  QueueMask queues = QueueMask::None;  // logical queues that access it
  // Accessed from more than one logical queue: create with
  // VK_SHARING_MODE_CONCURRENT (when those queues map to distinct families).
  bool concurrent = false;
  friend bool operator==(const ResourceDesc&, const ResourceDesc&) = default;
};

// Relative sizes round down and never below one texel.
ResolvedImageDesc resolveImageDesc(const ImageDesc& desc, uint32_t outputWidth, uint32_t outputHeight);

std::string_view toString(ResourceKind kind);
std::string_view toString(ResourceType type);

}  // namespace sg::graph
