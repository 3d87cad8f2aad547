#pragma once
// The textures material layers declare of their own, on the GPU as descriptor
// set 2: per layer for its decoupled variant, per material for its forward
// variant (its layers' textures in stack order). Loaded the first time a
// frame needs them, so only visible materials' textures are ever read.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/plugin/registry.hpp>

namespace sg::render {

inline constexpr uint32_t kLayerTextureSet = 2;

// Some textures as one descriptor set (binding i = texture i).
class TextureSet {
 public:
  TextureSet(gpu::Device& device, const std::vector<const plugin::LayerTexture*>& textures, const std::string& owner);
  ~TextureSet();
  TextureSet(const TextureSet&) = delete;
  TextureSet& operator=(const TextureSet&) = delete;
  VkDescriptorSetLayout layout() const { return layout_; }
  VkDescriptorSet set() const { return set_; }

 private:
  VkDevice device_;
  std::vector<gpu::Image> images_;
  VkSampler sampler_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

class LayerTextures {
 public:
  LayerTextures(gpu::Device& device, const plugin::Registry& registry) : device_(device), registry_(registry) {}
  // nullptr when the layer (or no layer of the material) declares textures.
  const TextureSet* forLayer(const plugin::MaterialLayer& layer);
  const TextureSet* forMaterial(const plugin::MaterialStack& material);

 private:
  const TextureSet* get(const std::string& key, const std::vector<const plugin::LayerTexture*>& textures,
                        const std::string& owner);
  gpu::Device& device_;
  const plugin::Registry& registry_;
  std::map<std::string, std::unique_ptr<TextureSet>> sets_;
};

}  // namespace sg::render
