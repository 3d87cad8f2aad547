#pragma once
// What a pass plugin gets while its frame is declared: the graph, the scene
// and camera, the visible draws split by how they are shaded this frame, the
// pass's parameters, the named frame resources, and per-renderer state that a
// package keeps across frames (e.g. decoupled shading's shadel space).
#include <map>
#include <span>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/plugin/frame_description.hpp>
#include <shadelgraph/render/depth_pass_draws.hpp>
#include <shadelgraph/render/scene_view.hpp>
#include <shadelgraph/render/shadow_views.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

// Whether the forward frame draws a depth pre-pass before forward-opaque:
// Auto decides from overdraw measured with occlusion queries
// (passes/z-prepass/z_prepass_choice.hpp, the rule in z_prepass_rule.hpp); frames with
// decoupled objects always have it (shadel-mark and composite test its depth).
enum class ZPrepass { Auto, On, Off };

// The camera and output of one frame.
struct FrameInputs {
  const scene::Scene& scene;
  gpu::Device& device;
  gpu::GraphExecutor& executor;  // to bind a package's own persistent and imported resources
  const std::vector<scene::ShadingMode>& objectModes;  // per scene instance: its requested mode this frame
  std::span<const glm::vec4> drawSpheres;  // per draw: its world bounding sphere (xyz centre, w radius)
  std::span<const scene::Bounds> drawBounds;  // per draw: its world bounding box (the sphere holds it)
  uint64_t frameNumber = 0;
  glm::vec3 cameraPosition{0.0f};
  // Pixels an object of size 1 covers at distance 1 (perspective); 0 for orthographic.
  float pixelsPerUnitAtUnitDistance = 0.0f;
  glm::mat4 viewProjection{1.0f};  // world to clip (Vulkan depth 0..1), for culling
  uint32_t width = 0, height = 0;
  // Occlusion culling's per-renderer state; null when the frame is not to be occlusion-culled.
  DrawCulling* culling = nullptr;
  ZPrepass zPrepass = ZPrepass::Auto;
  // This frame's joint matrices and morph weights; null when the scene has no skinned or morphed object.
  const DeformationFrame* deformation = nullptr;
  // This frame's shadow maps (the frame uniforms hold their matrices and slots); empty: no shadows.
  std::span<const ShadowView> shadowViews;
  // The pixel (x right, y down) whose object is asked for this frame (RenderSettings::pick).
  std::optional<glm::uvec2> pick;
};

// Indices into GpuScene::draws() of the draws inside the view frustum. All
// start forward; a package that shades some decoupled moves them over in its
// passes' prepare step.
struct FrameDraws {
  std::vector<uint32_t> forward, decoupled;
};

class FrameContext {
 public:
  // `frame`: the passes being declared (passesBetween); null: none known.
  FrameContext(graph::RenderGraph& graph, const FrameInputs& inputs, const SceneView& allDraws,
               std::map<std::string, std::shared_ptr<void>>& states, const plugin::ResolvedFrame* frame = nullptr);

  graph::RenderGraph& graph() { return graph_; }
  const FrameInputs& inputs() const { return inputs_; }
  const GpuScene& gpuScene() const { return all_.scene; }
  const plugin::Registry& registry() const { return all_.materials; }
  FrameDraws& draws() { return draws_; }
  // Forward and decoupled draws together, in draw order (for depth-only passes).
  std::span<const uint32_t> visibleDraws();
  // A scene view over some of this frame's draws (the span must outlive the frame's declaration).
  SceneView view(std::span<const uint32_t> draws) const;
  // The culled draw commands a cull pass publishes for the passes after it (see readDrawCommands).
  DrawCommands& drawCommands() { return drawCommands_; }
  // Draws a package hands the depth pre-pass (set in its prepare step; depth_pass_draws.hpp).
  std::optional<DepthPassDraws>& depthPassDraws() { return depthPassDraws_; }

  // The frame resource's current version; throws naming the pass when no pass wrote it.
  graph::ResourceHandle read(const std::string& resource) const;
  bool has(const std::string& resource) const { return resources_.count(resource) != 0; }
  const std::map<std::string, graph::ResourceHandle>& resources() const { return resources_; }
  // Publishes a new version of a frame resource the pass declared it writes.
  void write(const std::string& resource, graph::ResourceHandle handle);

  // The running pass and its parameters (defaults merged with the frame's values).
  const std::string& passName() const;
  const nlohmann::json& parameters() const;
  template <class T>
  T parameter(const std::string& name) const {
    return parameters().at(name).get<T>();
  }
  // The HDR image holds debug colours: tone mapping shows them unchanged.
  bool debugColors = false;

  // Per-renderer state a package provided (Renderer::provideState); throws when absent.
  template <class T>
  T& state(const std::string& key) {
    return *static_cast<T*>(stateOrThrow(key));
  }

  // Per-renderer state a pass keeps for itself across frames, made on first use.
  template <class T>
  T& ownState(const std::string& key) {
    std::shared_ptr<void>& slot = states_[key];
    if (!slot) slot = std::make_shared<T>();
    return *static_cast<T*>(slot.get());
  }

  void setPass(const plugin::ResolvedPass* pass) { pass_ = pass; }
  // The frame's passes after the running one and before the one named
  // `until` (every later one when the frame has none of that name): e.g.
  // what reads a resource before a later pass could write it.
  std::span<const plugin::ResolvedPass> passesBetween(const std::string& until) const;
  // Whether a pass of that name comes after the running one in this frame.
  bool runsLater(const std::string& pass) const;

 private:
  void* stateOrThrow(const std::string& key) const;

  graph::RenderGraph& graph_;
  const FrameInputs& inputs_;
  const SceneView& all_;
  std::map<std::string, std::shared_ptr<void>>& states_;
  FrameDraws draws_;
  DrawCommands drawCommands_;
  std::optional<DepthPassDraws> depthPassDraws_;
  std::vector<uint32_t> visible_;
  std::map<std::string, graph::ResourceHandle> resources_;
  const plugin::ResolvedPass* pass_ = nullptr;
  const plugin::ResolvedFrame* frame_ = nullptr;
};

}  // namespace sg::render
