#pragma once
// A frame recipe puts the passes of one frame on the render graph: the
// forward recipe (plugins/forward), the decoupled-shading recipe, or a
// user's own. It gets the scene to draw and the output to write.
#include <functional>

#include <glm/glm.hpp>

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/scene/scene.hpp>
#include <shadelgraph/render/scene_view.hpp>

namespace sg::render {

struct FrameInputs {
  SceneView view;  // view.draws: every draw of the scene
  const scene::Scene& scene;
  gpu::Device& device;
  gpu::GraphExecutor& executor;  // to bind the recipe's own persistent and imported resources
  glm::vec3 cameraPosition{0.0f};
  // Pixels an object of size 1 covers at distance 1 (perspective); 0 for orthographic.
  float pixelsPerUnitAtUnitDistance = 0.0f;
  glm::mat4 viewProjection{1.0f};  // world to clip (Vulkan depth 0..1), for culling
  uint32_t width = 0, height = 0;
  graph::ResourceHandle output;  // imported 8-bit sRGB colour image
};

// Declares the frame's passes; returns the final version of the output.
using FrameRecipe = std::function<graph::ResourceHandle(graph::RenderGraph&, const FrameInputs&)>;

}  // namespace sg::render
