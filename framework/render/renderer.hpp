#pragma once
// Renders frames of one scene through a frame description: uploads the scene,
// keeps each object's shading mode, turns the resolved frame into render-graph
// passes every frame (each registered pass's prepare, then declare), owns the
// output image and the graph executor, and reads the result back.
#include <map>
#include <memory>
#include <optional>

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/readback.hpp>
#include <shadelgraph/plugin/frame_description.hpp>
#include <shadelgraph/render/draw_culling.hpp>
#include <shadelgraph/render/frame_context.hpp>
#include <shadelgraph/render/frame_uniforms.hpp>
#include <shadelgraph/render/gpu_scene.hpp>
#include <shadelgraph/render/layer_textures.hpp>
#include <shadelgraph/render/object_deformation.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

struct RenderSettings {
  uint32_t width = 1280;
  uint32_t height = 720;
  int camera = -1;  // index into the scene's cameras; -1: the first, or framing of the bounds
  std::optional<scene::Camera> cameraOverride;  // e.g. a pose along a camera path; wins over `camera`
  bool aliasing = true;
  // Seconds into the scene's object motion (scene::ObjectMotion): when set,
  // every object that moves is placed at that time before the frame (its
  // setObjectTransform). Unset: objects keep the transforms they have.
  std::optional<float> time;
  // Skip draws hidden behind others (tested against this frame's depth of the draws visible last frame).
  bool occlusionCulling = true;
  // The depth pre-pass: per frame (Auto), or forced on or off to compare (frames with decoupled objects keep it).
  ZPrepass zPrepass = ZPrepass::Auto;
  // Frames recorded while earlier ones run (a frame's tail, e.g. a shade
  // frame, left running): 1 or 2.
  uint32_t framesInFlight = 1;
  bool readback = true;  // read the output image back (FrameResult::image)
  bool keepPlan = false;  // copy the compiled frame into FrameResult::plan (the viewer shows it)
  // A pixel (x right, y down) whose object the frame's pick pass reads back
  // (FrameResult::picked); the frame has the pass's work only while this is set.
  std::optional<glm::uvec2> pick;
};

struct FrameResult {
  gpu::HostImage image;
  gpu::FrameTimings timings;
  uint64_t transientBytes = 0;
  bool planReused = false;                  // the graph was the last frame's: its plan was not compiled again
  std::optional<graph::CompiledPlan> plan;  // with RenderSettings::keepPlan
  // With RenderSettings::pick: whether a pass of the frame wrote the pick
  // resource (plugin::kPickResource), and the scene instance it found there.
  bool pickAnswered = false;
  std::optional<uint32_t> picked;
};

class Renderer {
 public:
  // `registry`: the passes the frame names and the materials the scene's objects name.
  Renderer(gpu::Device& device, const scene::Scene& scene, const plugin::Registry& registry,
           plugin::ResolvedFrame frame);
  ~Renderer();

  void setFrame(plugin::ResolvedFrame frame) { frame_ = std::move(frame); }
  const plugin::ResolvedFrame& frame() const { return frame_; }
  // State a package's passes share across frames, found by FrameContext::state.
  void provideState(const std::string& key, std::shared_ptr<void> state) { states_[key] = std::move(state); }
  // An object's requested shading mode, from the next frame on (initially the scene's).
  void setObjectMode(uint32_t instance, scene::ShadingMode mode);
  const std::vector<scene::ShadingMode>& objectModes() const { return modes_; }
  // An object's world transform (rigid or not) and its material (a registered
  // layer stack), from the next frame on.
  void setObjectTransform(uint32_t instance, const glm::mat4& world);
  void setObjectMaterial(uint32_t instance, const std::string& materialStack);
  // A skinned or morphed object's joint matrices (world space: joint node
  // world * inverse bind, scene::jointWorldMatrices) and morph weights, from
  // the next frame on; the skinning pass deforms its vertices on the GPU.
  void setObjectDeformation(uint32_t instance, std::span<const glm::mat4> worldJoints, std::span<const float> weights);

  // Declares and compiles the frame `render` would run (with real memory requirements).
  graph::CompiledPlan plan(const RenderSettings& settings);
  FrameResult render(const RenderSettings& settings);
  // Waits for the frames still running (a tail left in flight) and returns
  // the timings of the tails completed since the last call.
  std::vector<gpu::FrameTimings> finishFrames();
  const GpuScene& gpuScene() const { return gpuScene_; }
  const DrawCulling& culling() const { return culling_; }
  scene::Camera camera(const RenderSettings& settings) const;

 private:
  struct Frame;
  std::unique_ptr<Frame> declare(const RenderSettings& settings);
  void importPick(Frame& frame, glm::uvec2 pixel, uint32_t width, uint32_t height);
  // The object's draws' bounding spheres from its world transform (and its deformed bounds).
  void updateSpheres(uint32_t instance, const glm::mat4& world);

  gpu::Device& device_;
  const scene::Scene& scene_;
  const plugin::Registry& registry_;
  plugin::ResolvedFrame frame_;
  std::map<std::string, std::shared_ptr<void>> states_;
  std::vector<scene::ShadingMode> modes_;
  uint64_t frameNumber_ = 0;
  LayerTextures layerTextures_;
  GpuScene gpuScene_;
  std::vector<scene::Bounds> drawBounds_;  // world bounding box of every draw (the sphere holds it)
  std::vector<glm::vec4> drawSpheres_;     // world bounding sphere of every draw, for frustum culling
  DrawCulling culling_;
  ObjectDeformation deformation_;
  gpu::Buffer frameUniforms_[2];  // one per frame in flight
  gpu::Buffer lights_[2];         // the frame's lights (kBindLights), one per frame in flight
  gpu::Buffer noLightGrid_;       // bound as the light grid when the frame has none (header dims.w = 0)
  std::vector<GpuLight> frameLights_;
  std::optional<gpu::Image> output_;
  gpu::Buffer pickReadback_;  // made at the first pick
  gpu::GraphExecutor executor_;
};

}  // namespace sg::render
