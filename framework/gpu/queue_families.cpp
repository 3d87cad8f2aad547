#include <shadelgraph/gpu/queue_families.hpp>

#include <algorithm>

namespace sg::gpu {

std::vector<uint32_t> QueueFamilyChoice::distinct() const {
  std::vector<uint32_t> families;
  for (const uint32_t f : {graphics, compute, transfer})
    if (std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
  return families;
}

std::optional<QueueFamilyChoice> chooseQueueFamilies(std::span<const VkQueueFamilyProperties> families) {
  const auto find = [&](VkQueueFlags want, VkQueueFlags avoid) -> std::optional<uint32_t> {
    for (uint32_t i = 0; i < families.size(); ++i)
      if (families[i].queueCount > 0 && (families[i].queueFlags & want) == want && !(families[i].queueFlags & avoid))
        return i;
    return std::nullopt;
  };
  const auto graphics = find(VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT, 0);
  if (!graphics) return std::nullopt;
  const auto compute = find(VK_QUEUE_COMPUTE_BIT, VK_QUEUE_GRAPHICS_BIT);
  const auto transfer = find(VK_QUEUE_TRANSFER_BIT, VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT);
  return QueueFamilyChoice{*graphics, compute.value_or(*graphics), transfer.value_or(*graphics)};
}

}  // namespace sg::gpu
