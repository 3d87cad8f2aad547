#pragma once
// Renders frames of one scene through a frame recipe: uploads the scene, owns
// the output image and the graph executor, and reads the result back.
#include <memory>
#include <optional>

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/readback.hpp>
#include <shadelgraph/render/frame_recipe.hpp>
#include <shadelgraph/render/gpu_scene.hpp>
#include <shadelgraph/render/layer_textures.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

struct RenderSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  int camera = -1;  // index into the scene's cameras; -1: the first, or framing of the bounds
  std::optional<scene::Camera> cameraOverride;  // e.g. a pose along a camera path; wins over `camera`
  bool aliasing = true;
};

struct FrameResult {
  gpu::HostImage image;
  gpu::FrameTimings timings;
  uint64_t transientBytes = 0;
};

class Renderer {
 public:
  // `materials`: the registered layers and materials the scene's objects name.
  Renderer(gpu::Device& device, const scene::Scene& scene, FrameRecipe recipe, const plugin::Registry& materials);
  ~Renderer();

  // Declares and compiles the frame `render` would run (with real memory requirements).
  graph::CompiledPlan plan(const RenderSettings& settings);
  FrameResult render(const RenderSettings& settings);
  const GpuScene& gpuScene() const { return gpuScene_; }
  scene::Camera camera(const RenderSettings& settings) const;

 private:
  struct Frame;
  std::unique_ptr<Frame> declare(const RenderSettings& settings);

  gpu::Device& device_;
  const scene::Scene& scene_;
  FrameRecipe recipe_;
  const plugin::Registry& materials_;
  LayerTextures layerTextures_;
  GpuScene gpuScene_;
  gpu::Buffer frameUniforms_;
  std::optional<gpu::Image> output_;
  gpu::GraphExecutor executor_;
};

}  // namespace sg::render
