#pragma once
// What passes need from the gpu layer, in one place: the context, memory,
// shader sources and compiler, the persisted pipeline cache, and pipelines
// built once by name and reused every frame.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <variant>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/memory.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/gpu/pipeline_cache.hpp>
#include <shadelgraph/gpu/shader_compiler.hpp>
#include <shadelgraph/gpu/shader_library.hpp>

namespace sg::gpu {

struct DeviceOptions {
  std::filesystem::path cacheDirectory = defaultCacheDirectory();  // empty: no disk caches
};

class Device {
 public:
  Device(Context& context, const DeviceOptions& options = {});
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  Context& context() { return context_; }
  MemoryAllocator& memory() { return memory_; }
  ShaderLibrary& shaders() { return library_; }
  ShaderCompiler& compiler() { return compiler_; }
  PipelineCache& pipelineCache() { return pipelineCache_; }
  // A clamp-to-edge nearest sampler for full-screen and image-processing passes.
  VkSampler nearestSampler() const { return nearest_; }

  // The pipeline built from `desc` the first time `name` is asked for.
  const Pipeline& pipeline(const std::string& name, const std::function<ComputePipelineDesc()>& desc);
  const Pipeline& pipeline(const std::string& name, const std::function<GraphicsPipelineDesc()>& desc);
  // Has `name` been built (what a frame needed so far)?
  bool hasPipeline(const std::string& name) const { return pipelines_.count(name) != 0; }

 private:
  Context& context_;
  MemoryAllocator memory_;
  ShaderLibrary library_;
  ShaderCompiler compiler_;
  PipelineCache pipelineCache_;
  std::map<std::string, Pipeline> pipelines_;
  VkSampler nearest_ = VK_NULL_HANDLE;
};

}  // namespace sg::gpu
