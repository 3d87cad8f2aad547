#include <shadelgraph/graph/memory_requirements.hpp>

#include <algorithm>

namespace sg::graph {

MemoryRequirements estimateMemoryRequirements(const ResourceDesc& desc) {
  if (desc.type == ResourceType::Buffer) return {std::max<uint64_t>(desc.bufferSize, 1), 256, ~uint32_t{0}};
  const ResolvedImageDesc& image = desc.image;
  uint64_t bytes = 0;
  uint64_t w = image.width, h = image.height, d = image.depth;
  for (uint32_t mip = 0; mip < std::max(image.mipLevels, 1u); ++mip) {
    bytes += w * h * d;
    w = std::max<uint64_t>(w / 2, 1);
    h = std::max<uint64_t>(h / 2, 1);
    d = std::max<uint64_t>(d / 2, 1);
  }
  bytes *= uint64_t{bytesPerTexel(image.format)} * std::max(image.layers, 1u) * std::max(image.samples, 1u);
  return {std::max<uint64_t>(bytes, 1), 65536, ~uint32_t{0}};
}

}  // namespace sg::graph
