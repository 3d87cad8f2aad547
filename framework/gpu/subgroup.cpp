#include "subgroup.hpp"

namespace sg::gpu {

uint32_t subgroupSize(VkPhysicalDevice device) {
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &subgroup;
  vkGetPhysicalDeviceProperties2(device, &properties);
  return subgroup.subgroupSize;
}

}  // namespace sg::gpu
