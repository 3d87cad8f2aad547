#pragma once
// The render graph's plain-data vocabulary mapped 1:1 onto Vulkan.
#include <vulkan/vulkan.h>

#include <shadelgraph/graph/format.hpp>
#include <shadelgraph/graph/sync_types.hpp>
#include <shadelgraph/graph/usage.hpp>

namespace sg::gpu {

VkFormat toVk(graph::Format format);
VkPipelineStageFlags2 toVk(graph::PipelineStage stages);
VkAccessFlags2 toVk(graph::AccessFlag access);
VkImageLayout toVk(graph::Layout layout);
VkImageUsageFlags toVk(graph::ImageUsage usage);
VkBufferUsageFlags toVk(graph::BufferUsage usage);

}  // namespace sg::gpu
