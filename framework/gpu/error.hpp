#pragma once
// Errors from the gpu layer: thrown as exceptions so callers (CLI, tests) can
// report them and exit cleanly instead of aborting.
#include <stdexcept>
#include <string>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class GpuError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

const char* resultName(VkResult result);

// Throws GpuError naming the call when result is not VK_SUCCESS.
void check(VkResult result, const char* what);

}  // namespace sg::gpu

#define SG_VK(call) ::sg::gpu::check((call), #call)
