#pragma once
// What persistent layers and shading reuse (--shade-rate above 1) keep
// between frames: for each persistent layer, two layer images (this frame's
// and last frame's, swapped every frame); with reuse, the shade storage image
// (one: stable allocation keeps a chunk where it was, so its shading stays in
// place) and the shade stamps. Where last frame stored a shadel needs no
// second remap table: a chunk stored then and now is at the same place
// (chunk_slots.glsl). None of it exists until a visible object's material has
// a persistent layer or the shade rate is above 1.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugins {

struct PersistentLayerHandles {
  graph::ResourceHandle current, history;
};

class LayerHistory {
 public:
  // The remap table, declared on the graph and bound on the executor.
  // `layers`: the persistent layers this frame runs; `frame`: the frame
  // number (parity). `keepShading`: also the shade storage kept across frames.
  struct Declared {
    graph::ResourceHandle remap;
    std::map<std::string, PersistentLayerHandles> layers;
    graph::ResourceHandle shaded;  // keepShading: the shade storage, kept across frames
    graph::ResourceHandle stamps;  // keepShading: per physical chunk, the frame its shading was computed in
    // Last frame (the frame just before, not an earlier one) ran the same
    // persistent layers and reuse with this storage size.
    bool valid = false;
  };
  // `outputKey`: what else stored values depend on (the output size: a
  // resize reshades everything); history is valid only while it stays equal.
  Declared declare(graph::RenderGraph& graph, gpu::Device& device, gpu::GraphExecutor& executor,
                   const plugin::Registry& registry, const std::vector<std::string>& layers, bool keepShading,
                   uint32_t width, uint32_t height, uint64_t remapBytes, uint64_t frame, const std::string& outputKey);
  uint64_t bytes() const;  // history storage held (the layer image pairs and the stamps)

 private:
  gpu::Buffer& remap(gpu::Device& device, uint64_t bytes);
  // The shade storage kept across frames, (re)created at this size.
  graph::ResourceHandle declareStorage(graph::RenderGraph& graph, gpu::Device& device, gpu::GraphExecutor& executor,
                                       uint32_t width, uint32_t height);
  // The image pair of `name`, (re)created at this size; declared and bound for this frame's parity.
  PersistentLayerHandles declareImagePair(graph::RenderGraph& graph, gpu::Device& device,
                                          gpu::GraphExecutor& executor, const std::string& name, graph::Format format,
                                          uint32_t width, uint32_t height, uint32_t current);
  // The stamp buffer, (re)created for `chunks` chunks.
  graph::ResourceHandle declareStamps(graph::RenderGraph& graph, gpu::Device& device, gpu::GraphExecutor& executor,
                                      uint64_t chunks);
  gpu::Buffer remap_;
  gpu::Buffer stamps_;
  gpu::Image storage_;
  std::map<std::string, std::array<gpu::Image, 2>> images_;
  std::map<std::string, uint32_t> formatBytes_;
  std::string lastKey_;  // the persistent layers, reuse and size of the last declared frame
  uint64_t lastFrame_ = ~0ull;  // its frame number
};

}  // namespace sg::plugins
