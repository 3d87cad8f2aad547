#pragma once
// A scene uploaded for drawing: one vertex and one index buffer for all
// meshes (skinned and morphed objects get vertex ranges of their own), textures with mips, samplers, and one descriptor set per material
// (set 1 of the material shaders, see framework/plugin/shaders/scene_material.glsl).
#include <vector>

#include <glm/glm.hpp>
#include <shadelgraph/render/shaders/frame_interface.h>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/buffer_view.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/render/gpu_deformation.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::render {

struct GpuVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec4 tangent;
  glm::vec2 uv0;
  glm::vec2 uv1;
  glm::vec4 color;
};

// Vertex `i` of `primitive` as uploaded (absent attributes get their defaults).
GpuVertex toGpuVertex(const scene::Primitive& primitive, size_t i);

// The vertex input every scene pipeline uses (locations 0..5 of object.glsl).
gpu::VertexInput sceneVertexInput();

// One primitive of one instance: what a draw call needs.
struct DrawItem {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  uint32_t material = 0;
  uint32_t instance = 0;
  glm::mat4 world{1.0f};
  scene::AlphaMode alphaMode = scene::AlphaMode::Opaque;
  bool doubleSided = false;
  // Its material samples no texture and its mesh has no COLOR_0: a gltf-pbr
  // forward draw then needs only position and normal interpolated.
  bool plainSurface = false;
  std::string materialStack;  // the instance's layer stack ("gltf-pbr" unless the scene says otherwise)
  uint32_t primitive = 0;     // which primitive of the instance's mesh
  // An opaque, rigid primitive whose mesh is a closed outward surface
  // (scene::Primitive::closedSurface): seen from outside, its back faces are
  // hidden even when the material is double-sided (SceneView::backFacesHidden).
  bool closedSurface = false;
};

// Push constants of object.glsl.
using ObjectConstants = shader::SgObjectConstants;

class GpuScene {
 public:
  GpuScene(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  const std::vector<DrawItem>& draws() const { return draws_; }
  // Every draw of scene instance `instance` gets this world transform / layer stack.
  void setInstanceWorld(uint32_t instance, const glm::mat4& world);
  void setInstanceMaterialStack(uint32_t instance, const std::string& materialStack);
  VkDescriptorSetLayout materialSetLayout() const { return materialLayout_; }
  VkDescriptorSet materialSet(uint32_t material) const { return materialSets_[material]; }
  VkBuffer vertexBuffer() const { return vertices_.handle(); }
  // The vertex buffer itself: the skinning pass imports it into frames that deform objects.
  const gpu::Buffer& vertexStorage() const { return vertices_; }
  // Skinned and morphed objects: each has vertex ranges of its own, rewritten per frame.
  const GpuDeformation& deformation() const { return deformation_; }
  VkBuffer indexBuffer() const { return indices_.handle(); }
  // The same two buffers as uniform texel buffers, for layer shading (passes/layer-shade/shadel_context.glsl):
  // vertices as RG32F texels (kVertexTexels a vertex), indices as R32UI.
  VkBufferView vertexTexels() const { return vertexTexels_.handle(); }
  VkBufferView indexTexels() const { return indexTexels_.handle(); }
  static constexpr uint32_t kVertexTexels = sizeof(GpuVertex) / 8;
  // Every draw's index, 0..n-1 (a SceneView's draw list for all objects).
  const std::vector<uint32_t>& allDraws() const { return allDraws_; }
  // A 1x1 white texture (shader-read layout): the stand-in for a frame image a frame did not make.
  VkImageView whiteView() const { return textures_[textures_.size() - 2].view(); }
  // Binds the vertex and index buffers.
  void bindGeometry(VkCommandBuffer cmd) const;
  size_t triangleCount() const;

 private:
  void uploadGeometry(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene);
  void uploadTextures(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene);
  void createMaterials(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene);

  VkDevice device_;
  gpu::Buffer vertices_, indices_;
  gpu::BufferView vertexTexels_, indexTexels_;  // after the buffers: destroyed before them
  GpuDeformation deformation_;
  std::vector<DrawItem> draws_;
  std::vector<uint32_t> allDraws_;
  std::vector<gpu::Image> textures_;  // scene textures, then white, then flat normal
  std::vector<VkSampler> samplers_;
  std::vector<gpu::Buffer> materialBuffers_;
  VkDescriptorSetLayout materialLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool materialPool_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> materialSets_;
};

}  // namespace sg::render
