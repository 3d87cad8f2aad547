// An object's detail levels as shadel-mark's vertex shader hands them to its
// fragment shader (flat): level 0's size, the level count and each level's
// origin in remap entries, packed x | y << 16 (a level's origin is a multiple
// of SG_ENTRY_SIZE inside a sheet of at most 2^19 shadels a side, so 13 bits
// each). A level's size is level0Size >> level (sg::shadel::DetailLevels), so
// the rectangle is whole again without a buffer read.
#ifndef SG_SHADEL_MARK_LEVELS_GLSL
#define SG_SHADEL_MARK_LEVELS_GLSL

const uint kMarkLevelsLocation = 4u;                    // after the alpha test's inputs
const uint kMarkLevelOriginVectors = kMaxLevels / 4u;  // four levels per uvec4

uint sgPackLevelOrigin(uvec2 origin) {
  uvec2 entry = origin >> SG_ENTRY_SIZE_LOG2;
  return entry.x | (entry.y << 16u);
}

// The rectangle of `level` (allocatedSize is not needed here and left 0).
SgLevelRect sgUnpackLevelRect(uvec4 origins[kMarkLevelOriginVectors], uvec2 levels, uint level) {
  uvec4 four = origins[level >> 2u];
  uint packed = four[level & 3u];
  SgLevelRect rect;
  rect.origin = uvec2(packed & 0xFFFFu, packed >> 16u) << SG_ENTRY_SIZE_LOG2;
  rect.size = levels.x >> level;
  rect.allocatedSize = 0u;
  return rect;
}

#endif
