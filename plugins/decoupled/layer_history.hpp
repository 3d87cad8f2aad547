#pragma once
// What persistent layers and shading reuse (--shade-rate above 1) keep
// between frames: for each persistent layer, two layer images (this frame's
// and last frame's, swapped every frame); with reuse, two shade storage
// images likewise; and, shared by all, a second remap table (last frame's, to
// find where a shadel was stored). None of it exists until a visible object's
// material has a persistent layer or the shade rate is above 1.
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
  // The remap table this frame writes and, when `layers` is not empty, last
  // frame's; declared on the graph and bound on the executor. `layers`: the
  // persistent layers this frame runs; `frame`: the frame number (parity).
  // `keepShading`: also the shade storage pair (what shade-reuse copies from).
  struct Declared {
    graph::ResourceHandle remap, previousRemap;
    std::map<std::string, PersistentLayerHandles> layers;
    PersistentLayerHandles shaded;  // keepShading: this frame's shade storage and last frame's
    PersistentLayerHandles stamps;  // keepShading: per physical chunk, the frame its shading was computed in
    // Last frame (the frame just before, not an earlier one) ran the same
    // persistent layers and reuse with this storage size.
    bool valid = false;
  };
  // `outputKey`: what else stored values depend on (the output size: a
  // resize reshades everything); history is valid only while it stays equal.
  Declared declare(graph::RenderGraph& graph, gpu::Device& device, gpu::GraphExecutor& executor,
                   const plugin::Registry& registry, const std::vector<std::string>& layers, bool keepShading,
                   uint32_t width, uint32_t height, uint64_t remapBytes, uint64_t frame, const std::string& outputKey);
  uint64_t bytes() const;  // history storage held (second remap and the layer images)

 private:
  gpu::Buffer& remap(gpu::Device& device, uint32_t index, uint64_t bytes);
  // The image pair of `name`, (re)created at this size; declared and bound for this frame's parity.
  PersistentLayerHandles declareImagePair(graph::RenderGraph& graph, gpu::Device& device,
                                          gpu::GraphExecutor& executor, const std::string& name, graph::Format format,
                                          uint32_t width, uint32_t height, uint32_t current);
  // The stamp buffer pair, (re)created for `chunks` chunks; declared and bound for this frame's parity.
  PersistentLayerHandles declareStamps(graph::RenderGraph& graph, gpu::Device& device, gpu::GraphExecutor& executor,
                                       uint64_t chunks, uint32_t current);
  std::array<gpu::Buffer, 2> remaps_;
  std::array<gpu::Buffer, 2> stamps_;
  std::map<std::string, std::array<gpu::Image, 2>> images_;
  std::map<std::string, uint32_t> formatBytes_;
  std::string lastKey_;  // the persistent layers, reuse and size of the last declared frame
  uint64_t lastFrame_ = ~0ull;  // its frame number
};

}  // namespace sg::plugins
