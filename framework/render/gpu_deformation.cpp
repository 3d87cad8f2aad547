#include <shadelgraph/render/gpu_deformation.hpp>

#include <shadelgraph/render/buffer_upload.hpp>
#include <shadelgraph/render/gpu_scene.hpp>

namespace sg::render {

GpuDeformation::GpuDeformation(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene,
                               std::span<const DeformedPrimitive> primitives) {
  jointFirst_.assign(scene.instances.size(), shader::kSkinNone);
  weightFirst_.assign(scene.instances.size(), shader::kSkinNone);
  for (const DeformedPrimitive& d : primitives) {
    if (jointFirst_[d.instance] != shader::kSkinNone) continue;
    const scene::Instance& instance = scene.instances[d.instance];
    jointFirst_[d.instance] = jointCount_;
    weightFirst_[d.instance] = weightCount_;
    if (instance.skin >= 0) jointCount_ += uint32_t(scene.skins[size_t(instance.skin)].joints.size());
    weightCount_ += uint32_t(scene.meshes[size_t(instance.mesh)].weights.size());
  }
  std::vector<GpuVertex> rest;
  std::vector<shader::SgSkinInfluence> influences;
  std::vector<shader::SgMorphDelta> deltas;
  for (const DeformedPrimitive& d : primitives) {
    const scene::Primitive& p = *d.primitive;
    const auto count = uint32_t(p.positions.size());
    const bool skinned = p.skinned() && scene.instances[d.instance].skin >= 0;
    DeformedRange& range = ranges_.emplace_back();
    range.instance = d.instance;
    range.push = {.restFirst = uint32_t(rest.size()),
                  .vertexFirst = d.vertexFirst,
                  .vertexCount = count,
                  .influenceFirst = skinned ? uint32_t(influences.size()) : shader::kSkinNone,
                  .jointFirst = jointFirst_[d.instance],
                  .deltaFirst = uint32_t(deltas.size()),
                  .targetCount = uint32_t(p.targets.size()),
                  .weightFirst = weightFirst_[d.instance]};
    for (uint32_t v = 0; v < count; ++v) rest.push_back(toGpuVertex(p, v));
    if (skinned)
      for (uint32_t v = 0; v < count; ++v)
        influences.push_back({p.joints0[v], p.weights0[v], p.joints1.empty() ? glm::uvec4(0) : p.joints1[v],
                              p.weights1.empty() ? glm::vec4(0.0f) : p.weights1[v]});
    for (const scene::MorphTarget& t : p.targets)
      for (uint32_t v = 0; v < count; ++v)
        deltas.push_back({t.positions.empty() ? glm::vec3(0.0f) : t.positions[v],
                          t.normals.empty() ? glm::vec3(0.0f) : t.normals[v],
                          t.tangents.empty() ? glm::vec3(0.0f) : t.tangents[v]});
  }
  // Vulkan has no empty buffers: an unused table gets one zero element (never read).
  if (influences.empty()) influences.emplace_back();
  if (deltas.empty()) deltas.emplace_back();
  rest_ = uploadBuffer(context, memory, rest.data(), rest.size() * sizeof(GpuVertex), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       "rest vertices");
  influences_ = uploadBuffer(context, memory, influences.data(), influences.size() * sizeof(influences[0]),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "skin influences");
  deltas_ = uploadBuffer(context, memory, deltas.data(), deltas.size() * sizeof(deltas[0]),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, "morph deltas");
}

}  // namespace sg::render
