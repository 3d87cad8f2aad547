#include <shadelgraph/render/layer_textures.hpp>

#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/render/texture_upload.hpp>

namespace sg::render {

TextureSet::TextureSet(gpu::Device& device, const std::vector<const plugin::LayerTexture*>& textures,
                       const std::string& owner)
    : device_(device.context().device()) {
  for (const auto* texture : textures) {
    image::Rgba8Image pixels;
    try {
      pixels = image::readPng(texture->file);
    } catch (const std::exception& e) {
      throw plugin::PluginError(owner + ": texture '" + texture->name + "': " + e.what());
    }
    images_.push_back(uploadTexture(device.context(), device.memory(), pixels.width, pixels.height,
                                    pixels.pixels.data(), texture->srgb, texture->name, "layer textures"));
  }
  VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sampler.magFilter = sampler.minFilter = VK_FILTER_LINEAR;
  sampler.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  sampler.addressModeU = sampler.addressModeV = sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  sampler.maxLod = VK_LOD_CLAMP_NONE;
  SG_VK(vkCreateSampler(device_, &sampler, nullptr, &sampler_));

  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (uint32_t i = 0; i < images_.size(); ++i)
    bindings.push_back({i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_ALL, nullptr});
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = uint32_t(bindings.size());
  layoutInfo.pBindings = bindings.data();
  SG_VK(vkCreateDescriptorSetLayout(device_, &layoutInfo, nullptr, &layout_));

  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(images_.size())};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = 1;
  poolInfo.poolSizeCount = 1;
  poolInfo.pPoolSizes = &size;
  SG_VK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_));
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout_;
  SG_VK(vkAllocateDescriptorSets(device_, &alloc, &set_));

  std::vector<VkDescriptorImageInfo> infos;
  for (const auto& image : images_)
    infos.push_back({sampler_, image.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  std::vector<VkWriteDescriptorSet> writes;
  for (uint32_t i = 0; i < infos.size(); ++i) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set_;
    w.dstBinding = i;
    w.descriptorCount = 1;
    w.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    w.pImageInfo = &infos[i];
    writes.push_back(w);
  }
  vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);
}

TextureSet::~TextureSet() {
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
  if (layout_) vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
  if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
}

const TextureSet* LayerTextures::get(const std::string& key, const std::vector<const plugin::LayerTexture*>& textures,
                                     const std::string& owner) {
  if (textures.empty()) return nullptr;
  auto& set = sets_[key];
  if (!set) set = std::make_unique<TextureSet>(device_, textures, owner);
  return set.get();
}

const TextureSet* LayerTextures::forLayer(const plugin::MaterialLayer& layer) {
  std::vector<const plugin::LayerTexture*> textures;
  for (const auto& texture : layer.textures) textures.push_back(&texture);
  return get("layer " + layer.name, textures, "material layer '" + layer.name + "' (plugin '" + layer.plugin + "')");
}

const TextureSet* LayerTextures::forMaterial(const plugin::MaterialStack& material) {
  std::vector<const plugin::LayerTexture*> textures;
  for (const auto& name : material.layers)
    for (const auto& texture : registry_.layer(name).textures) textures.push_back(&texture);
  return get("material " + material.name, textures,
             "material '" + material.name + "' (plugin '" + material.plugin + "')");
}

}  // namespace sg::render
