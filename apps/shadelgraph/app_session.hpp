#pragma once
// What the device commands share: a Vulkan context (validation from
// SG_VALIDATION), the gpu device with the built-in shaders, the scene, the
// plugin registry, and a renderer running a frame description (the built-in
// "decoupled" frame unless --frame-graph names another).
#include <memory>
#include <string>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/plugin/registry.hpp>
#include <shadelgraph/render/renderer.hpp>

#include <decoupled/decoupled_shading.hpp>
#include <shadelgraph/scene/camera_path.hpp>
#include <shadelgraph/scene/scene.hpp>

#include "command_options.hpp"

namespace sg::app {

struct AppSession {
  // mode: "" (each object's own), "forward", "decoupled" or "auto" for every object.
  // materials: plugin libraries or directories of them (--plugin, --plugin-dir),
  // loaded after those of $SG_PLUGIN_PATH, and a material for every object.
  AppSession(const std::string& scenePath, const std::string& mode = "", plugins::DecoupledSettings settings = {},
             const MaterialArgs& materials = {}, const FrameArgs& frame = {},
             const gpu::ContextOptions& contextOptions = gpu::ContextOptions::fromEnvironment());
  ~AppSession();
  // Non-zero (and a message on stderr) when validation reported anything.
  int validationExitCode() const;
  // A new renderer and decoupled shading with other settings (the viewer's
  // controls), on the same device and frame; objects' modes and materials are
  // the scene's again.
  void rebuildRenderer(const plugins::DecoupledSettings& settings);

  // Material layers, materials and passes: the built-ins and every plugin's.
  plugin::Registry registry;
  scene::Scene scene;
  std::vector<scene::CameraPath> cameraPaths;
  std::unique_ptr<gpu::Context> context;
  std::unique_ptr<gpu::Device> device;
  std::shared_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
};

}  // namespace sg::app
