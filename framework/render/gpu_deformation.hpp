#pragma once
// What skinning and morph targets need on the GPU, uploaded once with the
// scene: the rest pose of every deformed vertex range, the skinned vertices'
// joints and weights, and the morph targets' deltas (all read-only), plus the
// layout of the per-frame joint matrices and morph weights the renderer
// writes (one copy per frame in flight). passes/skinning turns them into the
// deformed vertices of the scene vertex buffer (see docs/skinning.md).
#include <span>
#include <vector>

#include <glm/glm.hpp>
#include <shadelgraph/render/shaders/deformation_interface.h>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

// One primitive of one deformed object (its own range of the scene vertex buffer).
struct DeformedRange {
  uint32_t instance = 0;
  shader::SgSkinningPush push;  // what the pass dispatches it with
};

// Where the vertices of one deformable object went: filled by GpuScene's upload.
struct DeformedPrimitive {
  uint32_t instance = 0;
  const scene::Primitive* primitive = nullptr;
  uint32_t vertexFirst = 0;  // its range in the scene vertex buffer
};

class GpuDeformation {
 public:
  GpuDeformation() = default;
  GpuDeformation(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene,
                 std::span<const DeformedPrimitive> primitives);

  bool empty() const { return ranges_.empty(); }
  const std::vector<DeformedRange>& ranges() const { return ranges_; }
  // Per scene instance: is it deformed, its first joint matrix and morph weight in the per-frame arrays.
  bool deformed(uint32_t instance) const { return instance < jointFirst_.size() && jointFirst_[instance] != shader::kSkinNone; }
  uint32_t jointFirst(uint32_t instance) const { return jointFirst_[instance]; }
  uint32_t weightFirst(uint32_t instance) const { return weightFirst_[instance]; }
  uint32_t jointCount() const { return jointCount_; }    // matrices per frame
  uint32_t weightCount() const { return weightCount_; }  // floats per frame
  const gpu::Buffer& rest() const { return rest_; }
  const gpu::Buffer& influences() const { return influences_; }
  const gpu::Buffer& deltas() const { return deltas_; }

 private:
  std::vector<DeformedRange> ranges_;
  std::vector<uint32_t> jointFirst_, weightFirst_;
  uint32_t jointCount_ = 0, weightCount_ = 0;
  gpu::Buffer rest_, influences_, deltas_;
};

// This frame's joint matrices and morph weights (the renderer's copy for the
// frame's slot), as the skinning pass binds them.
struct DeformationFrame {
  const GpuDeformation& deformation;
  const gpu::Buffer& joints;
  const gpu::Buffer& weights;
};

}  // namespace sg::render
