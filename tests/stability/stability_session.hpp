#pragma once
// A scene rendered forward or decoupled (the decoupled frame, every object in
// one mode) with validation on, any message failing the test, and each
// frame's HDR colour read back next to its 8-bit output.
#include <gtest/gtest.h>

#include <memory>
#include <optional>

#include <builtin_plugins.hpp>
#include <builtin_shaders.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "device_fixture.hpp"
#include "hdr_capture.hpp"

namespace sg::test {

struct StabilityFrame {
  gpu::HostImage ldr;            // the output, sRGB 8-bit
  std::vector<glm::vec4> hdr;    // the HDR colour before exposure, same size
  shader::SgExposure exposure{};  // what the exposure pass computed and tonemap applied
  plugins::DecoupledStats stats;  // of this frame (decoupled objects only)
};

class StabilitySession {
 public:
  // `exposure`, `lightCull`: those passes' parameters, when objects (e.g. {"adaptation": 0.5}).
  // `frame`: kHdrCapturedFrame (HDR before exposure) or kHdrFinalCapturedFrame (last before tonemap).
  StabilitySession(scene::Scene s, scene::ShadingMode mode, plugins::DecoupledSettings settings = {},
                   const nlohmann::json& exposure = nullptr, const char* frame = kHdrCapturedFrame,
                   const nlohmann::json& lightCull = nullptr)
      : scene_(std::move(s)), context_(validatedOptions()) {
    plugins::registerBuiltins(registry_);
    capture_.registerIn(registry_, exposure, lightCull);
    device_ = std::make_unique<gpu::Device>(context_);
    device_->shaders().add(gpu::builtinShaders());
    capture_.setDevice(*device_);
    auto made = plugins::makeDecoupledRenderer(*device_, scene_, registry_, mode, settings, frame);
    shading_ = std::move(made.shading);
    renderer_ = std::move(made.renderer);
  }
  ~StabilitySession() {
    renderer_.reset();
    shading_.reset();
    capture_ = HdrCapture{};  // its buffer comes from the device's allocator
    device_.reset();
    for (const auto& m : context_.validationLog().messages()) ADD_FAILURE() << "validation: " << m.text;
  }
  StabilityFrame render(uint32_t width, uint32_t height, std::optional<scene::Camera> camera = {}) {
    StabilityFrame f;
    f.ldr = renderer_->render({.width = width, .height = height, .cameraOverride = camera}).image;
    f.hdr = capture_.pixels();
    f.exposure = capture_.exposure();
    f.stats = shading_->stats();
    return f;
  }
  StabilityFrame render(uint32_t size, std::optional<scene::Camera> camera = {}) { return render(size, size, camera); }
  // The compiled frame `render` would run (what `shadelgraph graph` prints).
  graph::CompiledPlan plan(uint32_t width, uint32_t height, std::optional<scene::Camera> camera = {}) {
    return renderer_->plan({.width = width, .height = height, .cameraOverride = camera});
  }
  // The last frame's light grid (light_grid.h) as words; empty when the frame culled no lights.
  std::vector<uint32_t> lightGrid() const { return capture_.lightGrid(); }
  render::Renderer& renderer() { return *renderer_; }
  const scene::Scene& scene() const { return scene_; }

 private:
  scene::Scene scene_;
  plugin::Registry registry_;
  HdrCapture capture_;
  gpu::Context context_;
  std::shared_ptr<plugins::DecoupledShading> shading_;
  std::unique_ptr<gpu::Device> device_;
  std::unique_ptr<render::Renderer> renderer_;
};

}  // namespace sg::test
