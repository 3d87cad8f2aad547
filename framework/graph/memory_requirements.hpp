#pragma once

#include <shadelgraph/graph/resource_desc.hpp>

#include <cstdint>

namespace sg::graph {

// What vkGet{Image,Buffer}MemoryRequirements reports for one resource.
struct MemoryRequirements {
  uint64_t size = 0;
  uint64_t alignment = 1;
  uint32_t memoryTypeBits = ~uint32_t{0};
  friend bool operator==(const MemoryRequirements&, const MemoryRequirements&) = default;
};

// A device-free guess (texel bytes x extent x mips x layers x samples, 64 KiB
// image / 256 B buffer alignment, any memory type). Only for tools and tests
// without a device; the executor always hands in the real requirements.
MemoryRequirements estimateMemoryRequirements(const ResourceDesc& desc);

}  // namespace sg::graph
