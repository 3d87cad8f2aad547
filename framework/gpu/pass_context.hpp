#pragma once
// What a pass's execute callback records with: the command buffer, the
// physical resources behind its graph handles, per-frame descriptors, and
// dynamic-rendering helpers. Defines sg::PassContext, which framework/graph
// only names.
#include <initializer_list>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/graph/handles.hpp>

namespace sg {

namespace gpu {
class GraphExecutor;
}

struct ColorTarget {
  graph::ResourceHandle image;
  std::optional<VkClearColorValue> clear;  // absent: load
};

struct DepthTarget {
  graph::ResourceHandle image;
  std::optional<float> clear;  // absent: load
  bool readOnly = false;
};

class PassContext {
 public:
  VkCommandBuffer cmd() const { return cmd_; }
  gpu::Device& device() const { return device_; }
  gpu::DescriptorArena& descriptors() const { return descriptors_; }

  const gpu::Image& image(graph::ResourceHandle handle) const;
  const gpu::Buffer& buffer(graph::ResourceHandle handle) const;

  // vkCmdBeginRendering over the targets' full extent, with viewport and
  // scissor set to it. flipY: a negative-height viewport, so +Y is up in clip
  // space (the scene cameras' convention).
  void beginRendering(std::initializer_list<ColorTarget> colors, std::optional<DepthTarget> depth = {},
                      bool flipY = false) const;
  void endRendering() const { vkCmdEndRendering(cmd_); }
  // Bind a pipeline and, in one call, its set-0 descriptors.
  void bind(const gpu::Pipeline& pipeline, std::initializer_list<gpu::DescriptorWrite> writes = {}) const;
  void bind(const gpu::Pipeline& pipeline, std::span<const gpu::DescriptorWrite> writes) const;

 private:
  friend class gpu::GraphExecutor;
  PassContext(VkCommandBuffer cmd, gpu::Device& device, gpu::DescriptorArena& descriptors,
              const gpu::GraphExecutor& executor)
      : cmd_(cmd), device_(device), descriptors_(descriptors), executor_(executor) {}
  VkCommandBuffer cmd_;
  gpu::Device& device_;
  gpu::DescriptorArena& descriptors_;
  const gpu::GraphExecutor& executor_;
};

}  // namespace sg
