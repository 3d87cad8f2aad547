#pragma once
// Reads the HDR colour back: a pass registered like a plugin's, in a frame
// (kHdrCapturedFrame) that runs it after shading and before exposure, copying
// the RGBA16F target into a host-visible buffer; and the exposure pass's
// result, copied the same way between exposure and tonemap.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/plugin/registry.hpp>

#include <exposure/exposure_interface.h>

namespace sg {
class PassContext;
}

namespace sg::test {

inline constexpr const char* kHdrCapturedFrame = "hdr-captured";
// The same, with the HDR colour captured last before tonemap: after bloom when the frame has it.
inline constexpr const char* kHdrFinalCapturedFrame = "hdr-final-captured";

class HdrCapture {
 public:
  // Adds the capture passes, kHdrCapturedFrame and kHdrFinalCapturedFrame to `registry` (with
  // `exposure` as the exposure pass's parameters and `lightCull` as light-cull's when they are
  // objects); the device is the one the frames run on.
  void registerIn(plugin::Registry& registry, const nlohmann::json& exposure = nullptr,
                  const nlohmann::json& lightCull = nullptr);
  void setDevice(gpu::Device& device) { device_ = &device; }
  // The last frame's HDR colour, row by row (call after the frame completed).
  std::vector<glm::vec4> pixels() const;
  // The last frame's exposure (EV100, the factor tonemap applied, the metering).
  shader::SgExposure exposure() const;
  // The last frame's light grid as words (light_grid.h), empty when it had none.
  std::vector<uint32_t> lightGrid() const;
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  void record(PassContext& ctx, const gpu::Image& hdr, const gpu::Image& copy);

  gpu::Device* device_ = nullptr;
  gpu::Buffer buffer_;
  gpu::Buffer exposure_;
  std::shared_ptr<gpu::Buffer> lightGrid_;  // shared with the frame's copy pass
  uint32_t width_ = 0, height_ = 0;
};

}  // namespace sg::test
