#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {

const char* resultName(VkResult result) {
  switch (result) {
#define SG_CASE(x) case x: return #x;
    SG_CASE(VK_SUCCESS) SG_CASE(VK_NOT_READY) SG_CASE(VK_TIMEOUT) SG_CASE(VK_INCOMPLETE)
    SG_CASE(VK_ERROR_OUT_OF_HOST_MEMORY) SG_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    SG_CASE(VK_ERROR_INITIALIZATION_FAILED) SG_CASE(VK_ERROR_DEVICE_LOST)
    SG_CASE(VK_ERROR_MEMORY_MAP_FAILED) SG_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    SG_CASE(VK_ERROR_EXTENSION_NOT_PRESENT) SG_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    SG_CASE(VK_ERROR_INCOMPATIBLE_DRIVER) SG_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    SG_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED) SG_CASE(VK_ERROR_FRAGMENTED_POOL)
    SG_CASE(VK_ERROR_OUT_OF_POOL_MEMORY) SG_CASE(VK_ERROR_UNKNOWN)
#undef SG_CASE
    default: return "VkResult(?)";
  }
}

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) throw GpuError(std::string(what) + " failed: " + resultName(result));
}

}  // namespace sg::gpu
