#pragma once
#include <string>
#include <vector>

#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/plugin/material_layer.hpp>
#include <decoupled_frame.hpp>

namespace sg::passes {

// One layer run on some objects, with the graph resources it touches.
struct LayerShadeStep {
  const plugin::MaterialLayer* layer = nullptr;
  std::vector<uint32_t> objects;               // decoupled object indices: one indirect dispatch each
  graph::ResourceHandle output;                // its own layer image, or the shaded colour
  std::vector<graph::ResourceHandle> inputs;   // the images of layer->reads, in order
  std::vector<graph::ResourceHandle> frameInputs;  // the frame resources of layer->frameInputs, in order
  graph::ResourceHandle history;               // persistent: last frame's image of this layer
  uint32_t persistentSlot = 0;                 // persistent: its layer_reuse counters
};

// Last frame, for persistent layers: whether the layers' history images
// describe the current storage layout (a chunk stored then and now is at the
// same place: stable allocation).
struct LayerHistory {
  bool valid = false;
};

// One layer-shade pass (async compute): for each step, the layer's decoupled
// variant (generated from its source) dispatched once per object over its
// work list, a workgroup per 8x8 chunk. Steps' outputs get their new versions.
void addLayerShade(graph::RenderGraph& graph, DecoupledFrame& frame, std::string name,
                   std::vector<LayerShadeStep>& steps, const LayerHistory& history);
// A layer's pipeline: its generated variant, set 0 and push constants; the
// pass adds set 1 (the scene material) and set 2 (the layer's textures).
// `rowsPerInvocation`: chunkRowsPerInvocation.
gpu::ComputePipelineDesc layerShadePipeline(const plugin::MaterialLayer& layer, uint32_t rowsPerInvocation);

}  // namespace sg::passes
