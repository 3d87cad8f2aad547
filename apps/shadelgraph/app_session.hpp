#pragma once
// What the device commands share: a Vulkan context (validation from
// SG_VALIDATION), the gpu device with the built-in shaders, the scene, and a
// renderer running the forward recipe.
#include <memory>
#include <string>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/render/renderer.hpp>

#include <decoupled/decoupled_shading.hpp>
#include <shadelgraph/scene/camera_path.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::app {

struct AppSession {
  // mode: "" (each object's own), "forward", "decoupled" or "auto" for every object.
  AppSession(const std::string& scenePath, const std::string& mode = "", plugins::DecoupledSettings settings = {});
  ~AppSession();
  // Non-zero (and a message on stderr) when validation reported anything.
  int validationExitCode() const;

  scene::Scene scene;
  std::vector<scene::CameraPath> cameraPaths;
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<gpu::Device> device;
  std::unique_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
};

}  // namespace sg::app
