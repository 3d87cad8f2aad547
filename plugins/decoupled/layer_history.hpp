#pragma once
// What persistent layers keep between frames: for each, two layer images
// (this frame's and last frame's, swapped every frame) and, shared by all, a
// second remap table (last frame's, to find where a shadel was stored). None
// of it exists until a visible object's material has a persistent layer.
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
  struct Declared {
    graph::ResourceHandle remap, previousRemap;
    std::map<std::string, PersistentLayerHandles> layers;
    bool valid = false;  // last frame ran the same persistent layers with this storage size
  };
  Declared declare(graph::RenderGraph& graph, gpu::Device& device, gpu::GraphExecutor& executor,
                   const plugin::Registry& registry, const std::vector<std::string>& layers, uint32_t width,
                   uint32_t height, uint64_t remapBytes, uint64_t frame);
  uint64_t bytes() const;  // history storage held (second remap and the layer images)

 private:
  gpu::Buffer& remap(gpu::Device& device, uint32_t index, uint64_t bytes);
  std::array<gpu::Buffer, 2> remaps_;
  std::map<std::string, std::array<gpu::Image, 2>> images_;
  std::map<std::string, uint32_t> formatBytes_;
  std::string lastKey_;  // the persistent layers and size of the last frame
};

}  // namespace sg::plugins
