#pragma once
// What scene passes draw: the uploaded scene, this frame's uniform buffer
// (camera, lights; written by the host before the frame is submitted) and the
// materials (layer stacks) the draws name.
#include <map>
#include <span>
#include <string>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/plugin/registry.hpp>
#include <shadelgraph/render/gpu_scene.hpp>
#include <shadelgraph/render/layer_textures.hpp>

namespace sg::render {

struct SceneView {
  const GpuScene& scene;
  const gpu::Buffer& frameUniforms;
  std::span<const uint32_t> draws;  // the draws (indices into scene.draws()) the pass takes
  const plugin::Registry& materials;
  LayerTextures& layerTextures;  // the layers' own textures, loaded when first drawn
  // The frame resources when the view was made (what layers' frameInputs sample).
  std::map<std::string, graph::ResourceHandle> frameImages = {};
};

// Push constants, cull mode and front face (clockwise when the world matrix
// mirrors) for one draw, then the indexed draw.
void drawItem(VkCommandBuffer cmd, const gpu::Pipeline& pipeline, const DrawItem& draw, uint32_t objectId);

}  // namespace sg::render
