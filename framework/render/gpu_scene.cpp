#include <shadelgraph/render/gpu_scene.hpp>

#include <algorithm>
#include <bit>
#include <cstring>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/plugin/material_stack.hpp>
#include <shadelgraph/render/buffer_upload.hpp>
#include <shadelgraph/render/gltf_material_stack.hpp>
#include <shadelgraph/render/texture_upload.hpp>

namespace sg::render {
namespace {

// Mirrors MaterialBlock in framework/plugin/shaders/scene_material.glsl (std140).
struct GpuTextureSlot {
  glm::vec4 row0, row1;
};
constexpr uint32_t kTextureSlots = 12;  // the core five, then the material extensions' seven
struct GpuMaterial {
  glm::vec4 baseColorFactor;
  glm::vec4 emissiveFactor;
  glm::vec4 params;
  glm::uvec4 flags;
  glm::vec4 clearcoat;  // factor, roughness, normal scale, -
  glm::vec4 sheen;      // colour, roughness
  glm::vec4 specular;   // colour factor x dielectric f0 from the ior, specular factor
  GpuTextureSlot slots[kTextureSlots];
};

VkSamplerAddressMode toVk(scene::WrapMode m) {
  switch (m) {
    case scene::WrapMode::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case scene::WrapMode::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case scene::WrapMode::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkFilter toVk(scene::Filter f) { return f == scene::Filter::Nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }


}  // namespace

gpu::VertexInput sceneVertexInput() {
  gpu::VertexInput input;
  input.bindings.push_back({0, sizeof(GpuVertex), VK_VERTEX_INPUT_RATE_VERTEX});
  input.attributes = {
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(GpuVertex, normal)},
      {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertex, tangent)},
      {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv0)},
      {4, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(GpuVertex, uv1)},
      {5, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(GpuVertex, color)},
  };
  return input;
}

GpuScene::GpuScene(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene)
    : device_(context.device()) {
  uploadGeometry(context, memory, scene);
  uploadTextures(context, memory, scene);
  createMaterials(context, memory, scene);
}

GpuScene::~GpuScene() {
  if (materialPool_) vkDestroyDescriptorPool(device_, materialPool_, nullptr);
  if (materialLayout_) vkDestroyDescriptorSetLayout(device_, materialLayout_, nullptr);
  for (VkSampler s : samplers_) vkDestroySampler(device_, s, nullptr);
}

GpuVertex toGpuVertex(const scene::Primitive& p, size_t i) {
  return {p.positions[i], p.normals.empty() ? glm::vec3(0, 1, 0) : p.normals[i],
          p.tangents.empty() ? glm::vec4(1, 0, 0, 1) : p.tangents[i], p.uv0.empty() ? glm::vec2(0) : p.uv0[i],
          p.uv1.empty() ? glm::vec2(0) : p.uv1[i], p.colors.empty() ? glm::vec4(1) : p.colors[i]};
}

void GpuScene::uploadGeometry(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene) {
  std::vector<GpuVertex> vertices;
  std::vector<uint32_t> indices;
  struct Range {
    uint32_t firstIndex, indexCount;
    int32_t vertexOffset;
    int material;
  };
  std::vector<std::vector<Range>> meshRanges;
  for (const auto& mesh : scene.meshes) {
    auto& ranges = meshRanges.emplace_back();
    for (const auto& p : mesh.primitives) {
      ranges.push_back({uint32_t(indices.size()), uint32_t(p.indices.size()), int32_t(vertices.size()), p.material});
      for (size_t i = 0; i < p.positions.size(); ++i) vertices.push_back(toGpuVertex(p, i));
      indices.insert(indices.end(), p.indices.begin(), p.indices.end());
      // Every primitive starts at a multiple of 3: layer-shade reads a triangle's indices as one uvec3.
      indices.resize((indices.size() + 2) / 3 * 3, 0u);
    }
  }
  std::vector<DeformedPrimitive> deformed;
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const auto& inst = scene.instances[i];
    const scene::Mesh& mesh = scene.meshes[size_t(inst.mesh)];
    // A deformed object gets vertices of its own: the skinning pass writes its pose there.
    const bool deforms = mesh.deformable();
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      Range r = meshRanges[size_t(inst.mesh)][p];
      if (deforms) {
        r.vertexOffset = int32_t(vertices.size());
        deformed.push_back({i, &mesh.primitives[p], uint32_t(r.vertexOffset)});
        const scene::Primitive& primitive = mesh.primitives[p];
        for (size_t v = 0; v < primitive.positions.size(); ++v) vertices.push_back(toGpuVertex(primitive, v));
      }
      const auto& m = scene.materials[size_t(r.material)];
      const bool textured = m.baseColorTexture.present() || m.metallicRoughnessTexture.present() ||
                            m.normalTexture.present() || m.occlusionTexture.present() || m.emissiveTexture.present();
      const bool plain = !textured && mesh.primitives[p].colors.empty();
      // Skins and morphs may fold a closed surface; blending and alpha masks show what is behind the front.
      const bool closed = mesh.primitives[p].closedSurface && !deforms && m.alphaMode == scene::AlphaMode::Opaque;
      draws_.push_back({r.firstIndex, r.indexCount, r.vertexOffset, uint32_t(r.material), i, inst.world, m.alphaMode,
                        m.doubleSided, plain, inst.material.empty() ? gltfMaterialStack(m) : inst.material, uint32_t(p),
                        closed});
    }
  }
  if (vertices.empty()) throw gpu::GpuError("the scene has no triangles to draw");
  for (uint32_t i = 0; i < draws_.size(); ++i) allDraws_.push_back(i);
  // Concurrent: the skinning pass writes it on the graphics queue, layer shading reads it on async compute.
  vertices_ = uploadBuffer(context, memory, vertices.data(), vertices.size() * sizeof(GpuVertex),
                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                               VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                               VK_BUFFER_USAGE_TRANSFER_SRC_BIT,  // read back by tests
                           "vertices",
                           /*concurrent*/ !deformed.empty());
  indices_ = uploadBuffer(context, memory, indices.data(), indices.size() * 4,
                          VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                              VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                          "indices");
  static_assert(sizeof(GpuVertex) % 8 == 0 && alignof(GpuVertex) == 4, "a GpuVertex is a whole number of RG32F texels");
  vertexTexels_ = gpu::BufferView(context, vertices_.handle(), vertices_.size(), VK_FORMAT_R32G32_SFLOAT, 8,
                                  "vertices (RG32F texels)");
  indexTexels_ = gpu::BufferView(context, indices_.handle(), indices_.size(), VK_FORMAT_R32_UINT, 4,
                                 "indices (R32UI texels)");
  if (!deformed.empty()) deformation_ = GpuDeformation(context, memory, scene, deformed);
}

void GpuScene::uploadTextures(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene) {
  for (const auto& t : scene.textures) {
    if (t.pixels.empty()) throw gpu::GpuError("texture '" + t.name + "' has no decoded pixels");
    textures_.push_back(uploadTexture(context, memory, t.width, t.height, t.pixels.data(), t.srgb, t.name, "scene textures"));
  }
  const uint8_t white[4] = {255, 255, 255, 255}, flatNormal[4] = {128, 128, 255, 255};
  textures_.push_back(uploadTexture(context, memory, 1, 1, white, false, "white", "scene textures"));
  textures_.push_back(uploadTexture(context, memory, 1, 1, flatNormal, false, "flat normal", "scene textures"));

  std::vector<scene::Sampler> samplers = scene.samplers;
  if (samplers.empty()) samplers.push_back({});
  for (const auto& s : samplers) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = toVk(s.magFilter);
    info.minFilter = toVk(s.minFilter);
    info.mipmapMode = s.mipmapMode == scene::MipmapMode::Nearest ? VK_SAMPLER_MIPMAP_MODE_NEAREST : VK_SAMPLER_MIPMAP_MODE_LINEAR;
    info.addressModeU = toVk(s.wrapS);
    info.addressModeV = toVk(s.wrapT);
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    info.maxLod = s.mipmapMode == scene::MipmapMode::None ? 0.0f : VK_LOD_CLAMP_NONE;
    VkSampler sampler;
    SG_VK(vkCreateSampler(device_, &info, nullptr, &sampler));
    samplers_.push_back(sampler);
  }
}

void GpuScene::createMaterials(gpu::Context& context, gpu::MemoryAllocator& memory, const scene::Scene& scene) {
  std::vector<VkDescriptorSetLayoutBinding> bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_ALL, nullptr}};
  for (uint32_t b = 1; b <= kTextureSlots; ++b)
    bindings.push_back({b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_ALL, nullptr});
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = uint32_t(bindings.size());
  layoutInfo.pBindings = bindings.data();
  SG_VK(vkCreateDescriptorSetLayout(device_, &layoutInfo, nullptr, &materialLayout_));

  std::vector<scene::Material> materials = scene.materials;
  if (materials.empty()) materials.push_back({});
  const auto count = uint32_t(materials.size());
  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, count},
                                  {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, count * kTextureSlots}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = count;
  poolInfo.poolSizeCount = 2;
  poolInfo.pPoolSizes = sizes;
  SG_VK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &materialPool_));
  std::vector<VkDescriptorSetLayout> layouts(count, materialLayout_);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = materialPool_;
  alloc.descriptorSetCount = count;
  alloc.pSetLayouts = layouts.data();
  materialSets_.resize(count);
  SG_VK(vkAllocateDescriptorSets(device_, &alloc, materialSets_.data()));

  const size_t white = scene.textures.size(), flatNormal = white + 1;
  for (uint32_t i = 0; i < count; ++i) {
    const auto& m = materials[i];
    GpuMaterial g{};
    g.baseColorFactor = m.baseColorFactor;
    g.emissiveFactor = glm::vec4(m.emissiveFactor * m.emissiveStrength, m.normalScale);
    g.params = {m.metallicFactor, m.roughnessFactor, m.occlusionStrength, m.alphaCutoff};
    const scene::Clearcoat coat = m.clearcoat.value_or(scene::Clearcoat{});
    const scene::Sheen sheen = m.sheen.value_or(scene::Sheen{});
    const scene::Specular specular = m.specular.value_or(scene::Specular{});
    const float ior = m.ior.value_or(1.5f), iorF0 = (ior - 1.0f) * (ior - 1.0f) / ((ior + 1.0f) * (ior + 1.0f));
    g.clearcoat = {coat.factor, coat.roughnessFactor, coat.normalScale, 0.0f};
    g.sheen = glm::vec4(sheen.colorFactor, sheen.roughnessFactor);
    g.specular = glm::vec4(specular.colorFactor * iorF0, specular.factor);
    const auto refs = m.textureSlots();
    VkDescriptorImageInfo images[kTextureSlots];
    uint32_t present = 0;
    for (uint32_t slot = 0; slot < kTextureSlots; ++slot) {
      const auto& ref = refs[slot];
      const glm::mat3 t = ref.transform.matrix();
      // glm is column-major: row r of the affine is (t[0][r], t[1][r], t[2][r]).
      g.slots[slot].row0 = {t[0][0], t[1][0], t[2][0], 0.0f};
      g.slots[slot].row1 = {t[0][1], t[1][1], t[2][1], float(ref.texCoord)};
      size_t texture = slot == 2 || slot == 7 ? flatNormal : white;  // normalTexture, clearcoatNormalTexture
      VkSampler sampler = samplers_[0];
      if (ref.present()) {
        present |= 1u << slot;
        texture = size_t(ref.texture);
        sampler = samplers_[size_t(scene.textures[texture].sampler)];
      }
      images[slot] = {sampler, textures_[texture].view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    g.flags = {uint32_t(m.alphaMode), m.doubleSided ? 1u : 0u, present, m.unlit ? 1u : 0u};
    gpu::Buffer& ubo = materialBuffers_.emplace_back(
        context, memory,
        gpu::BufferDesc{sizeof(GpuMaterial), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryLocation::Upload, m.name, "materials"});
    ubo.write(&g, sizeof g);
    VkDescriptorBufferInfo bufferInfo{ubo.handle(), 0, sizeof(GpuMaterial)};
    std::vector<VkWriteDescriptorSet> writes;
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = materialSets_[i];
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    w.pBufferInfo = &bufferInfo;
    writes.push_back(w);
    for (uint32_t slot = 0; slot < kTextureSlots; ++slot) {
      w.dstBinding = slot + 1;
      w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      w.pBufferInfo = nullptr;
      w.pImageInfo = &images[slot];
      writes.push_back(w);
    }
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);
  }
}

void GpuScene::bindGeometry(VkCommandBuffer cmd) const {
  VkBuffer vb = vertices_.handle();
  VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
}

size_t GpuScene::triangleCount() const {
  size_t n = 0;
  for (const auto& d : draws_) n += d.indexCount / 3;
  return n;
}

void GpuScene::setInstanceWorld(uint32_t instance, const glm::mat4& world) {
  for (auto& draw : draws_)
    if (draw.instance == instance) draw.world = world;
}

void GpuScene::setInstanceMaterialStack(uint32_t instance, const std::string& materialStack) {
  for (auto& draw : draws_)
    if (draw.instance == instance) draw.materialStack = materialStack;
}

}  // namespace sg::render
