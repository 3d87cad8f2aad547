#pragma once
// What occlusion culling keeps per renderer: every draw's world bounding
// sphere on the GPU, and one indirect draw command per draw whose instance
// count says whether the draw was visible in the last culled frame (the
// draws the next frame puts in its depth first, before it tests the rest).
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/render/gpu_scene.hpp>

namespace sg::render {

class DrawCulling {
 public:
  DrawCulling(gpu::Context& context, gpu::MemoryAllocator& memory, const std::vector<DrawItem>& draws,
              std::span<const glm::vec4> spheres);

  uint32_t drawCount() const { return drawCount_; }
  const gpu::Buffer& spheres() const { return spheres_; }
  // VkDrawIndexedIndirectCommand per draw, instance count 1 when visible (all 0 at first).
  const gpu::Buffer& commands() const { return commands_; }
  VkDeviceSize commandBytes() const { return commands_.size(); }
  // Per draw: did the last culled frame find it visible? (Read on the host; frames are waited for.)
  std::vector<bool> lastVisible() const;
  // A draw whose object moved: the next cull tests its new bounding sphere.
  void setSphere(uint32_t draw, const glm::vec4& sphere);

 private:
  uint32_t drawCount_ = 0;
  gpu::Buffer spheres_, commands_;
};

// This frame's indirect draw commands once a cull pass wrote them: draws
// read their instance count (0: culled) from `buffer` at the draw's index.
struct DrawCommands {
  graph::ResourceHandle handle;  // the version passes read; invalid: nothing culled, draw directly
  VkBuffer buffer = VK_NULL_HANDLE;
};

}  // namespace sg::render
