#include <shadelgraph/gpu/device.hpp>

#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

Device::Device(Context& context, const DeviceOptions& options)
    : context_(context),
      memory_(context),
      compiler_(library_, options.cacheDirectory),
      pipelineCache_(context, options.cacheDirectory.empty() ? std::filesystem::path()
                                                             : options.cacheDirectory / "pipelines.bin") {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = VK_LOD_CLAMP_NONE;
  SG_VK(vkCreateSampler(context.device(), &info, nullptr, &nearest_));
}

Device::~Device() {
  vkDeviceWaitIdle(context_.device());
  pipelines_.clear();
  vkDestroySampler(context_.device(), nearest_, nullptr);
}

const Pipeline& Device::pipeline(const std::string& name, const std::function<ComputePipelineDesc()>& desc) {
  if (auto it = pipelines_.find(name); it != pipelines_.end()) return it->second;
  ComputePipelineDesc d = desc();
  d.name = name;
  return pipelines_.emplace(name, Pipeline(context_, compiler_, pipelineCache_, d)).first->second;
}

const Pipeline& Device::pipeline(const std::string& name, const std::function<GraphicsPipelineDesc()>& desc) {
  if (auto it = pipelines_.find(name); it != pipelines_.end()) return it->second;
  GraphicsPipelineDesc d = desc();
  d.name = name;
  return pipelines_.emplace(name, Pipeline(context_, compiler_, pipelineCache_, d)).first->second;
}

}  // namespace sg::gpu
