#pragma once
// A VkPipelineCache persisted on disk, so a second run does not pay the
// driver's shader compilation (lavapipe's LLVM JIT) again.
#include <filesystem>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;

class PipelineCache {
 public:
  // An empty path keeps the cache in memory only.
  PipelineCache(const Context& context, std::filesystem::path file);
  ~PipelineCache();  // saves
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;
  VkPipelineCache handle() const { return cache_; }
  size_t loadedBytes() const { return loadedBytes_; }
  void save() const;

 private:
  VkDevice device_;
  std::filesystem::path file_;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
  size_t loadedBytes_ = 0;
};

}  // namespace sg::gpu
