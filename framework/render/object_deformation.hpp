#pragma once
// The renderer's per-frame side of skinning and morph targets: each deformed
// object's joint matrices (world space, as posed) and morph weights, the
// mesh-space bounds culling uses while its vertices move, and the host-written
// buffers (one per frame in flight) the skinning pass reads them from.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/render/gpu_deformation.hpp>
#include <shadelgraph/scene/deformation.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

class ObjectDeformation {
 public:
  // Starts from the scene's rest pose (nodes unanimated, the instances' morph weights).
  ObjectDeformation(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene,
                    const GpuDeformation& deformation);

  bool deformed(uint32_t instance) const { return deformation_.deformed(instance); }
  // The object's joint matrices (world space: joint node world * inverse bind)
  // and morph weights, from the next frame on. Sizes must match its skin and mesh.
  void set(uint32_t instance, std::span<const glm::mat4> worldJoints, std::span<const float> weights);
  void setWorld(uint32_t instance, const glm::mat4& world) {
    if (instance < worlds_.size()) worlds_[instance] = world;
  }
  // A mesh-space box around the object's deformed vertices (deformedBounds).
  scene::Bounds meshBounds(uint32_t instance) const;
  // Writes every object's joint matrices (relative to its world transform:
  // skinned vertices stay in mesh space) and weights into frame slot `slot`.
  DeformationFrame write(uint32_t slot);

 private:
  std::vector<glm::mat4> meshJoints(uint32_t instance) const;

  const GpuDeformation& deformation_;
  std::vector<glm::mat4> worlds_;
  std::vector<std::vector<glm::mat4>> worldJoints_;  // per instance (empty: not skinned)
  std::vector<std::vector<float>> weights_;          // per instance
  std::vector<scene::DeformationBounds> restBounds_;  // per instance (deformed ones only)
  gpu::Buffer joints_[2], weightBuffers_[2];       // one per frame in flight
};

}  // namespace sg::render
