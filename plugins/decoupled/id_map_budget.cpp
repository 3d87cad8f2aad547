#include <algorithm>

#include "id_map_budget.hpp"

#include <shadelgraph/shadel/detail_levels.hpp>

namespace sg::plugins {

uint64_t idMapTexels(uint32_t level0Size, uint32_t minLevelSize) {
  const shadel::DetailLevels levels = shadel::makeDetailLevels(level0Size, minLevelSize);
  uint64_t texels = 0;
  for (uint32_t l = 0; l < levels.levelCount; ++l) texels += uint64_t(levels.levelSize(l)) * levels.levelSize(l);
  return texels;
}

std::vector<uint32_t> fitIdMapSizes(std::vector<uint32_t> wanted, uint64_t budgetTexels, uint32_t minLevelSize,
                                    uint32_t floor) {
  uint64_t total = 0;
  for (const uint32_t size : wanted) total += idMapTexels(size, minLevelSize);
  while (total > budgetTexels) {
    const auto largest = std::max_element(wanted.begin(), wanted.end());
    if (largest == wanted.end() || *largest / 2 < floor) break;
    total -= idMapTexels(*largest, minLevelSize);
    *largest /= 2;
    total += idMapTexels(*largest, minLevelSize);
  }
  return wanted;
}

}  // namespace sg::plugins
