#pragma once
// Reads the HDR colour back: a pass registered like a plugin's, in a frame
// (kHdrCapturedFrame) that runs it after shading and before exposure, copying
// the RGBA16F target into a host-visible buffer.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/plugin/registry.hpp>

namespace sg {
class PassContext;
}

namespace sg::test {

inline constexpr const char* kHdrCapturedFrame = "hdr-captured";

class HdrCapture {
 public:
  // Adds the capture pass and kHdrCapturedFrame to `registry`; the device is the one the frames run on.
  void registerIn(plugin::Registry& registry);
  void setDevice(gpu::Device& device) { device_ = &device; }
  // The last frame's HDR colour, row by row (call after the frame completed).
  std::vector<glm::vec4> pixels() const;
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  void record(PassContext& ctx, const gpu::Image& hdr, const gpu::Image& copy);

  gpu::Device* device_ = nullptr;
  gpu::Buffer buffer_;
  uint32_t width_ = 0, height_ = 0;
};

}  // namespace sg::test
