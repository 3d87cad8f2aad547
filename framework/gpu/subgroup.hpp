#pragma once
// The device's subgroup size: how many invocations run as one SIMD unit
// (8 on lavapipe with 256-bit vectors, 32 or 64 on GPUs). Shaders that share
// per-workgroup setup size their workgroups by it.
#include <cstdint>

#include <vulkan/vulkan.h>

namespace sg::gpu {

uint32_t subgroupSize(VkPhysicalDevice device);

}  // namespace sg::gpu
