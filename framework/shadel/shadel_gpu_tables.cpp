#include <shadelgraph/shadel/shadel_gpu_tables.hpp>

namespace sg::shadel {

ShadelGpuTables buildGpuTables(const ShadelSpace& space) {
  ShadelGpuTables tables;
  tables.generation = space.generation();
  const auto& instances = space.instances();
  if (!instances.empty()) tables.instances.resize(static_cast<size_t>(instances.rbegin()->first) + 1);
  const uint32_t log2 = space.geometry().entriesPerSideLog2();
  for (const auto& [id, instance] : instances) {
    GpuShadelInstance& record = tables.instances[id];
    record.firstLevelRect = static_cast<uint32_t>(tables.levelRects.size());
    record.levelCount = instance.levels.levelCount;
    record.level0Size = instance.levels.level0Size;
    record.firstOwnedEntry = static_cast<uint32_t>(tables.ownedEntries.size());
    tables.levelRects.insert(tables.levelRects.end(), instance.rects.begin(), instance.rects.end());
    for (uint32_t level = 0; level < instance.blocks.size(); ++level) {
      const QuadtreeAllocator::Block& block = instance.blocks[level];
      const uint32_t side = 1u << block.sizeLog2;
      for (uint32_t y = 0; y < side; ++y)
        for (uint32_t x = 0; x < side; ++x)
          tables.ownedEntries.push_back({((block.origin.y + y) << log2) | (block.origin.x + x), id, level, 0});
    }
  }
  return tables;
}

}  // namespace sg::shadel
