#pragma once
// One-call sync2 barriers for code outside the render graph (uploads,
// readbacks, work inside one pass). The graph's own barriers come from its plan.
#include <vulkan/vulkan.h>

namespace sg::gpu {

struct Scope {
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

// A global memory (or, with no access bits, execution) dependency.
void memoryBarrier(VkCommandBuffer cmd, Scope src, Scope dst);

// Readbacks: make a compute shader's storage writes, or a copy's writes, visible to the host
// once the submission has been waited for.
void hostReadAfterCompute(VkCommandBuffer cmd);
void hostReadAfterCopy(VkCommandBuffer cmd);

// A layout transition of mips [firstMip, firstMip + mipCount) of a colour image.
void imageBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to, Scope src, Scope dst,
                  uint32_t firstMip = 0, uint32_t mipCount = VK_REMAINING_MIP_LEVELS);

}  // namespace sg::gpu
