#pragma once
// A scene rendered through the decoupled recipe with every object in a given
// shading mode, validation on (any message fails the test): what the
// decoupled and material-layer device tests share.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <builtin_plugins.hpp>
#include <builtin_shaders.hpp>
#include <decoupled/decoupled_package.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/render/renderer.hpp>
#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "device_fixture.hpp"

namespace sg::test {

// A camera panning sideways over the default scene, `step` units a frame (the shade-rate tests' path).
inline scene::Camera panCamera(int frame, float step = 0.15f) {
  scene::Camera camera{.name = "pan", .yfov = 0.9f, .znear = 0.05f, .zfar = 100.0f};
  const float x = -1.5f + step * float(frame);
  camera.world = scene::lookAtWorld({x, 2.0f, 6.0f}, {x * 0.5f, 1.0f, -1.0f});
  return camera;
}

// A camera at `eye` looking at `target` (the culling tests' views and paths).
inline scene::Camera lookAtCamera(glm::vec3 eye, glm::vec3 target) {
  scene::Camera c{.name = "path", .yfov = 0.9f, .znear = 0.1f, .zfar = 100.0f};
  c.world = scene::lookAtWorld(eye, target);
  return c;
}

// Test-name suffix of a test parameterized on both paths (Forward / Decoupled).
inline std::string pathName(const ::testing::TestParamInfo<scene::ShadingMode>& info) {
  return info.param == scene::ShadingMode::Forward ? "Forward" : "Decoupled";
}

// The default courtyard (64² chart) plus `count` spheres (radius 0.6) in a row
// along x from `first`, 2 apart, named "<name> <i>", shaded in `mode`.
inline scene::Scene courtyardWithSphereRow(const std::string& name, int count, glm::vec3 first, scene::ShadingMode mode,
                                           uint32_t textureSize = 64) {
  scene::Scene s = scene::makeDefaultScene(textureSize);
  scene::Primitive sphere = scene::makeSphere(0.6f, 24, 12);
  sphere.material = 0;
  scene::Mesh mesh{.name = name, .bounds = sphere.bounds};
  mesh.primitives.push_back(std::move(sphere));
  s.meshes.push_back(std::move(mesh));
  for (int i = 0; i < count; ++i)
    s.instances.push_back({int(s.meshes.size() - 1), glm::translate(glm::mat4(1.0f), first + glm::vec3(2.0f * float(i), 0, 0)),
                           name + " " + std::to_string(i), mode});
  return s;
}

// The index of the object called `name` (a test failure and 0 if there is none).
inline uint32_t instanceNamed(const scene::Scene& scene, const std::string& name) {
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == name) return i;
  ADD_FAILURE() << "no object '" << name << "' in the scene";
  return 0;
}

// A scene rendered through the decoupled recipe with every object in `mode`.
class Session {
 public:
  // `mode`: every object's mode; empty: each object's own (scene::Instance::shading).
  Session(scene::Scene s, std::optional<scene::ShadingMode> mode, plugins::DecoupledSettings settings = {},
          const plugin::Registry& registry = plugins::builtinRegistry(), const std::string& frame = "decoupled")
      : scene_(std::move(s)), context_(validatedOptions()) {
    device_ = std::make_unique<gpu::Device>(context_);
    device_->shaders().add(gpu::builtinShaders());
    auto made = plugins::makeDecoupledRenderer(*device_, scene_, registry, mode, settings, frame);
    shading_ = std::move(made.shading);
    renderer_ = std::move(made.renderer);
  }
  ~Session() {
    renderer_.reset();
    shading_.reset();  // its buffers come from the device's allocator
    device_.reset();
    for (const auto& m : context_.validationLog().messages()) ADD_FAILURE() << "validation: " << m.text;
  }
  gpu::HostImage render(uint32_t size, std::optional<scene::Camera> camera = {}) {
    return renderer_->render({.width = size, .height = size, .cameraOverride = camera}).image;
  }
  graph::CompiledPlan plan(uint32_t size, std::optional<scene::Camera> camera = {}) {
    return renderer_->plan({.width = size, .height = size, .cameraOverride = camera});
  }
  plugins::DecoupledStats stats() const { return shading_->stats(); }
  // Where each stored chunk is after the last frame (entry index * 64 + chunk -> physical chunk).
  std::map<uint64_t, uint32_t> chunkAddresses() const { return shading_->chunkAddresses(*device_); }
  const std::vector<plugins::ShadingChoice>& choices() const { return shading_->choices(); }
  const gpu::Device& device() const { return *device_; }
  const scene::Scene& scene() const { return scene_; }
  render::Renderer& renderer() { return *renderer_; }

  // The decoupled package's state, e.g. to set a fixed bias between frames.
  plugins::DecoupledShading& shading() { return *shading_; }

 private:
  scene::Scene scene_;
  gpu::Context context_;
  std::shared_ptr<plugins::DecoupledShading> shading_;
  std::unique_ptr<gpu::Device> device_;
  std::unique_ptr<render::Renderer> renderer_;
};

// The forward image of `scene` at `settings`: the reference decoupled renders are compared with.
inline gpu::HostImage forwardImage(const scene::Scene& scene, const render::RenderSettings& settings) {
  Session forward(scene, scene::ShadingMode::Forward);
  return forward.renderer().render(settings).image;
}

}  // namespace sg::test
