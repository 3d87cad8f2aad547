#include <shadelgraph/gpu/pipeline_cache.hpp>

#include <fstream>
#include <iterator>
#include <vector>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

PipelineCache::PipelineCache(const Context& context, std::filesystem::path file)
    : device_(context.device()), file_(std::move(file)) {
  std::vector<char> data;
  if (!file_.empty()) {
    std::ifstream in(file_, std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(in), {});
  }
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  info.initialDataSize = data.size();
  info.pInitialData = data.data();
  // A cache from another driver or version is rejected by the driver (its
  // header carries the UUID); start empty then rather than fail.
  if (vkCreatePipelineCache(device_, &info, nullptr, &cache_) != VK_SUCCESS) {
    info.initialDataSize = 0;
    info.pInitialData = nullptr;
    SG_VK(vkCreatePipelineCache(device_, &info, nullptr, &cache_));
  } else {
    loadedBytes_ = data.size();
  }
}

PipelineCache::~PipelineCache() {
  save();
  vkDestroyPipelineCache(device_, cache_, nullptr);
}

void PipelineCache::save() const {
  if (file_.empty()) return;
  size_t size = 0;
  if (vkGetPipelineCacheData(device_, cache_, &size, nullptr) != VK_SUCCESS || size == 0) return;
  std::vector<char> data(size);
  if (vkGetPipelineCacheData(device_, cache_, &size, data.data()) != VK_SUCCESS) return;
  std::error_code ec;
  std::filesystem::create_directories(file_.parent_path(), ec);
  auto tmp = file_;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(data.data(), static_cast<std::streamsize>(size));
  }
  std::filesystem::rename(tmp, file_, ec);
}

}  // namespace sg::gpu
