#pragma once
// Which queue family each logical queue (graphics, async compute, transfer)
// runs on: a pure function of the device's family list, so that the path for
// devices with a separate compute family is tested without one.
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::gpu {

struct QueueFamilyChoice {
  uint32_t graphics = 0, compute = 0, transfer = 0;  // by logical queue (Queue's order)
  uint32_t of(uint32_t logicalQueue) const { return logicalQueue == 0 ? graphics : logicalQueue == 1 ? compute : transfer; }
  // The distinct families, graphics first: what CONCURRENT resources are shared between.
  std::vector<uint32_t> distinct() const;
};

// Graphics: the first family with graphics and compute. Async compute: the
// first compute family without graphics, else graphics'. Transfer: the first
// transfer-only family, else graphics'. Empty when no family has graphics + compute.
std::optional<QueueFamilyChoice> chooseQueueFamilies(std::span<const VkQueueFamilyProperties> families);

}  // namespace sg::gpu
