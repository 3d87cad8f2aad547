#include <bit>

#include <shadelgraph/shadel/detail_levels.hpp>

namespace sg::shadel {

bool DetailLevels::valid() const {
  return std::has_single_bit(level0Size) && levelCount >= 1 && levelCount <= kMaxDetailLevels &&
         levelCount <= static_cast<uint32_t>(std::countr_zero(level0Size)) + 1;
}

DetailLevels makeDetailLevels(uint32_t level0Size, uint32_t minLevelSize) {
  if (!std::has_single_bit(level0Size) || !std::has_single_bit(minLevelSize)) return {level0Size, 0};
  uint32_t count = 1;
  while ((level0Size >> count) >= minLevelSize && (level0Size >> count) > 0) ++count;
  if (count > kMaxDetailLevels) return {level0Size, 0};
  return {level0Size, count};
}

}  // namespace sg::shadel
