#include <shadelgraph/gpu/descriptors.hpp>

#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/gpu/pipeline.hpp>

namespace sg::gpu {

DescriptorArena::DescriptorArena(const Context& context, uint32_t maxSets) : device_(context.device()) {
  const VkDescriptorPoolSize sizes[] = {
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, maxSets * 8},   {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, maxSets * 4},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, maxSets * 8}, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, maxSets * 4},
      {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, maxSets * 4},           {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, maxSets * 4},
  };
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = maxSets;
  info.poolSizeCount = static_cast<uint32_t>(std::size(sizes));
  info.pPoolSizes = sizes;
  SG_VK(vkCreateDescriptorPool(device_, &info, nullptr, &pool_));
}

DescriptorArena::~DescriptorArena() { vkDestroyDescriptorPool(device_, pool_, nullptr); }

void DescriptorArena::reset() { SG_VK(vkResetDescriptorPool(device_, pool_, 0)); }

void DescriptorArena::bind(VkCommandBuffer cmd, const Pipeline& pipeline, std::span<const DescriptorWrite> writes) {
  VkDescriptorSetLayout layout = pipeline.setLayout();
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  VkDescriptorSet set;
  SG_VK(vkAllocateDescriptorSets(device_, &alloc, &set));

  std::vector<VkDescriptorBufferInfo> buffers;
  std::vector<VkDescriptorImageInfo> images;
  std::vector<VkBufferView> texelBuffers;
  buffers.reserve(writes.size());
  images.reserve(writes.size());
  texelBuffers.reserve(writes.size());
  std::vector<VkWriteDescriptorSet> vkWrites;
  for (const auto& w : writes) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.dstBinding = w.binding;
    write.descriptorCount = 1;
    for (const auto& b : pipeline.bindings())
      if (b.binding == w.binding) write.descriptorType = b.type;
    if (auto* buffer = std::get_if<BufferBinding>(&w.resource)) {
      buffers.push_back({buffer->buffer, buffer->offset, buffer->range});
      write.pBufferInfo = &buffers.back();
    } else if (auto* texels = std::get_if<TexelBufferBinding>(&w.resource)) {
      texelBuffers.push_back(texels->view);
      write.pTexelBufferView = &texelBuffers.back();
    } else {
      const auto& image = std::get<ImageBinding>(w.resource);
      images.push_back({image.sampler, image.view, image.layout});
      write.pImageInfo = &images.back();
    }
    vkWrites.push_back(write);
  }
  vkUpdateDescriptorSets(device_, static_cast<uint32_t>(vkWrites.size()), vkWrites.data(), 0, nullptr);
  vkCmdBindDescriptorSets(cmd, pipeline.bindPoint(), pipeline.layout(), 0, 1, &set, 0, nullptr);
}

}  // namespace sg::gpu
