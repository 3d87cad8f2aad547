#pragma once
// Where one detail level of one instance sits in the virtual sheet.
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace sg::shadel {

// std430 layout, mirrored by SgLevelRect in shaders/shadel_address.glsl.
struct LevelRect {
  glm::uvec2 origin{0};        // in shadels; a multiple of kEntrySize (64)
  uint32_t size = 0;           // shadels a side that the level uses: DetailLevels::levelSize
  uint32_t allocatedSize = 0;  // shadels a side reserved: size snapped up to whole remap entries (>= 64)

  bool operator==(const LevelRect&) const = default;
};
static_assert(sizeof(LevelRect) == 16);
static_assert(offsetof(LevelRect, size) == 8);
static_assert(offsetof(LevelRect, allocatedSize) == 12);

}  // namespace sg::shadel
