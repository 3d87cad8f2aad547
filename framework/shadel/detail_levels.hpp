#pragma once
// An object's chain of shading detail levels, like a mip chain: level 0 is
// the finest, a square of level0Size shadels (a power of two); each next
// level is half the size, down to minLevelSize. The triangle-ID maps and the
// shadel-space rectangles use the same chain, so a level-local shadel
// coordinate addresses both.
#include <cstdint>

namespace sg::shadel {

inline constexpr uint32_t kMaxDetailLevels = 16;
inline constexpr uint32_t kDefaultMinLevelSize = 8;  // one chunk: the coarsest level worth a triangle-ID map

struct DetailLevels {
  uint32_t level0Size = 0;  // power of two
  uint32_t levelCount = 0;  // 1..kMaxDetailLevels

  uint32_t levelSize(uint32_t level) const { return level0Size >> level; }
  bool valid() const;
  bool operator==(const DetailLevels&) const = default;
};

// Every level from level0Size down to minLevelSize (both powers of two; a
// level0Size below minLevelSize gives one level). Invalid sizes (zero, not a
// power of two, more than kMaxDetailLevels levels) give levelCount 0.
DetailLevels makeDetailLevels(uint32_t level0Size, uint32_t minLevelSize = kDefaultMinLevelSize);

}  // namespace sg::shadel
