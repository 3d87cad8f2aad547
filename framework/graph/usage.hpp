#pragma once

#include <shadelgraph/graph/bitmask.hpp>

#include <cstdint>
#include <string>

namespace sg::graph {

// Union of how the graph uses a resource, so the gpu layer can create it with
// exactly the VkImageUsageFlags / VkBufferUsageFlags it needs.

enum class ImageUsage : uint32_t {
  None = 0,
  ColorAttachment = 1u << 0,
  DepthAttachment = 1u << 1,
  Sampled = 1u << 2,
  Storage = 1u << 3,
  TransferSrc = 1u << 4,
  TransferDst = 1u << 5,
};
template <>
struct EnableBitmask<ImageUsage> : std::true_type {};

enum class BufferUsage : uint32_t {
  None = 0,
  Storage = 1u << 0,
  Uniform = 1u << 1,
  Vertex = 1u << 2,
  Index = 1u << 3,
  Indirect = 1u << 4,
  TransferSrc = 1u << 5,
  TransferDst = 1u << 6,
  UniformTexel = 1u << 7,  // read through a buffer view (Access::Sampled)
};
template <>
struct EnableBitmask<BufferUsage> : std::true_type {};

std::string toString(ImageUsage usage);
std::string toString(BufferUsage usage);

}  // namespace sg::graph
