#pragma once
// What scene passes draw: the uploaded scene, this frame's uniform buffer
// (camera) and lights (written by the host before the frame is submitted) and the
// materials (layer stacks) the draws name.
#include <map>
#include <span>
#include <string>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/graph/pass.hpp>
#include <shadelgraph/plugin/registry.hpp>
#include <shadelgraph/render/draw_culling.hpp>
#include <shadelgraph/render/gpu_scene.hpp>
#include <shadelgraph/render/layer_textures.hpp>

namespace sg::render {

struct SceneView {
  const GpuScene& scene;
  const gpu::Buffer& frameUniforms;
  const gpu::Buffer& lights;       // Light[frame.counts.x] (kBindLights)
  const gpu::Buffer& noLightGrid;  // the light grid's stand-in when the frame has none (render/light_binding.hpp)
  std::span<const uint32_t> draws;  // the draws (indices into scene.draws()) the pass takes
  const plugin::Registry& materials;
  LayerTextures& layerTextures;  // the layers' own textures, loaded when first drawn
  // The frame resources when the view was made (what layers' frameInputs sample).
  std::map<std::string, graph::ResourceHandle> frameImages = {};
  // The frame's culled draw commands, filled in when a cull pass declares.
  const DrawCommands* commands = nullptr;
  // Set by readDrawCommands: the draws' instance counts come from here.
  VkBuffer indirect = VK_NULL_HANDLE;
  // Per draw of the scene (index into scene.draws()), this frame: 1 when the
  // camera sees its closed surface from outside, so back faces may be culled
  // whatever the material says. Empty: none.
  std::span<const uint8_t> backFacesHidden = {};
};

// Does this frame's camera see draw `drawIndex` (into view.scene.draws()) from outside its closed surface?
inline bool backFacesHidden(const SceneView& view, uint32_t drawIndex) {
  return drawIndex < view.backFacesHidden.size() && view.backFacesHidden[drawIndex] != 0;
}

// The frame resource of the scene vertex buffer: present only in frames whose
// skinning pass deformed a visible object this frame (it writes it).
inline constexpr const char* kSceneVerticesResource = "scene.vertices";

// Declares the pass's read of the scene's vertices when this frame deformed
// some (every pass that reads GpuScene's vertex buffer calls it): vertex
// input by default, or e.g. StorageRead from a compute shader.
void readSceneGeometry(graph::Pass& pass, const SceneView& view, graph::Access access = graph::Access::Vertex,
                       graph::ShaderStage stages = graph::ShaderStage::None);

// The view a pass that draws `view.draws` records with: when this frame's
// draws were culled, the pass reads the commands (declared now, at the
// version current now) and draws indirectly, skipping culled draws.
SceneView readDrawCommands(graph::Pass& pass, SceneView view);

// Push constants, cull mode and front face (clockwise when the world matrix
// mirrors) for one draw, then the indexed draw: from indirect draw command
// `drawIndex` of `indirect` when it is set (culled draws have instance count 0).
// Back faces are culled when the material is single-sided or `hiddenBackFaces`
// (the camera is outside the draw's closed surface: backFacesHidden()).
void drawItem(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const DrawItem& draw, uint32_t objectId,
              VkBuffer indirect = VK_NULL_HANDLE, uint32_t drawIndex = 0, bool hiddenBackFaces = false);
// Draw `drawIndex` of the view's scene as `objectId`, culled when the view read
// draw commands, its back faces culled when single-sided or backFacesHidden().
void drawItem(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const SceneView& view, uint32_t drawIndex,
              uint32_t objectId);

}  // namespace sg::render
