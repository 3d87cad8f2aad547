#include <shadelgraph/render/draw_culling.hpp>

#include <algorithm>

namespace sg::render {

DrawCulling::DrawCulling(gpu::Context& context, gpu::MemoryAllocator& memory, const std::vector<DrawItem>& draws,
                         std::span<const glm::vec4> spheres)
    : drawCount_(uint32_t(draws.size())),
      spheres_(context, memory,
               {std::max<VkDeviceSize>(draws.size() * sizeof(glm::vec4), 16), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                gpu::MemoryLocation::Upload, "draw spheres", "culling"}),
      commands_(context, memory,
                {std::max<VkDeviceSize>(draws.size() * sizeof(VkDrawIndexedIndirectCommand), 20),
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, gpu::MemoryLocation::Upload,
                 "draw commands", "culling"}) {
  if (draws.empty()) return;
  spheres_.write(spheres.data(), spheres.size() * sizeof(glm::vec4));
  std::vector<VkDrawIndexedIndirectCommand> commands;
  // Nothing was visible before the first frame: it tests every draw.
  for (const auto& d : draws) commands.push_back({d.indexCount, 0, d.firstIndex, d.vertexOffset, 0});
  commands_.write(commands.data(), commands.size() * sizeof(VkDrawIndexedIndirectCommand));
}

std::vector<bool> DrawCulling::lastVisible() const {
  std::vector<bool> visible(drawCount_);
  const auto* commands = reinterpret_cast<const VkDrawIndexedIndirectCommand*>(commands_.mapped());
  for (uint32_t d = 0; d < drawCount_; ++d) visible[d] = commands[d].instanceCount != 0;
  return visible;
}

void DrawCulling::setSphere(uint32_t draw, const glm::vec4& sphere) {
  if (draw < drawCount_) spheres_.write(&sphere, sizeof sphere, draw * sizeof(glm::vec4));
}

}  // namespace sg::render
