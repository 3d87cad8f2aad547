#include <shadelgraph/render/object_deformation.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

#include <shadelgraph/scene/pose.hpp>

namespace sg::render {

ObjectDeformation::ObjectDeformation(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene,
                                     const GpuDeformation& deformation)
    : deformation_(deformation),
      worldJoints_(scene.instances.size()),
      weights_(scene.instances.size()),
      restBounds_(scene.instances.size()) {
  if (deformation.empty()) return;
  const std::vector<glm::mat4> rest = scene::poseNodes(scene, {}, 0.0f);
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const scene::Instance& instance = scene.instances[i];
    worlds_.push_back(instance.world);
    if (!deformed(i)) continue;
    if (instance.skin >= 0) worldJoints_[i] = scene::jointWorldMatrices(scene.skins[size_t(instance.skin)], rest);
    weights_[i] = instance.morphWeights;
    weights_[i].resize(scene.meshes[size_t(instance.mesh)].weights.size(), 0.0f);  // one per target, as laid out
    restBounds_[i] = scene::deformationBounds(scene.meshes[size_t(instance.mesh)]);
  }
  for (uint32_t slot = 0; slot < 2; ++slot) {
    // Vulkan has no empty buffers: an object without joints or weights still gets one element.
    joints_[slot] = gpu::Buffer(context, memory,
                                {std::max<VkDeviceSize>(deformation.jointCount(), 1) * sizeof(glm::mat4),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload, "joint matrices", "frame"});
    weightBuffers_[slot] = gpu::Buffer(context, memory,
                                       {std::max<VkDeviceSize>(deformation.weightCount(), 1) * sizeof(float),
                                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryLocation::Upload, "morph weights", "frame"});
  }
}

void ObjectDeformation::set(uint32_t instance, std::span<const glm::mat4> worldJoints, std::span<const float> weights) {
  if (!deformed(instance)) throw std::invalid_argument("object " + std::to_string(instance) + " is not skinned or morphed");
  if (worldJoints.size() != worldJoints_[instance].size() || weights.size() != weights_[instance].size())
    throw std::invalid_argument("object " + std::to_string(instance) + ": " + std::to_string(worldJoints.size()) +
                                " joints and " + std::to_string(weights.size()) + " morph weights for its " +
                                std::to_string(worldJoints_[instance].size()) + " and " +
                                std::to_string(weights_[instance].size()));
  worldJoints_[instance].assign(worldJoints.begin(), worldJoints.end());
  weights_[instance].assign(weights.begin(), weights.end());
}

std::vector<glm::mat4> ObjectDeformation::meshJoints(uint32_t instance) const {
  const glm::mat4 toMesh = glm::inverse(worlds_[instance]);
  std::vector<glm::mat4> out;
  for (const glm::mat4& joint : worldJoints_[instance]) out.push_back(toMesh * joint);
  return out;
}

scene::Bounds ObjectDeformation::meshBounds(uint32_t instance) const {
  return scene::deformedBounds(restBounds_[instance], meshJoints(instance), weights_[instance]);
}

DeformationFrame ObjectDeformation::write(uint32_t slot) {
  for (uint32_t i = 0; i < worldJoints_.size(); ++i) {
    if (!deformed(i)) continue;
    const std::vector<glm::mat4> joints = meshJoints(i);
    if (!joints.empty())
      joints_[slot].write(joints.data(), joints.size() * sizeof(glm::mat4), deformation_.jointFirst(i) * sizeof(glm::mat4));
    if (!weights_[i].empty())
      weightBuffers_[slot].write(weights_[i].data(), weights_[i].size() * sizeof(float),
                                 deformation_.weightFirst(i) * sizeof(float));
  }
  return {deformation_, joints_[slot], weightBuffers_[slot]};
}

}  // namespace sg::render
