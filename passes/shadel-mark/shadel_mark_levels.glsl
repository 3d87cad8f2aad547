// An object's detail levels as shadel-mark's vertex shader hands them to its
// fragment shader (flat, four words, so the fragment shader reads no table
// for them and the rasterizer sets up few inputs per triangle): level 0's
// size, the level count, the instance's first owned entry and its first level
// rectangle. A level's rectangle the fragment shader reads through a texel
// view (one gather for the level it marks). The rest follows from level 0's
// size (sg::shadel::DetailLevels, ShadelSpace): a level is level0Size >> level
// shadels a side and owns a square of max(size / SG_ENTRY_SIZE, 1) entries a
// side, listed level by level, row-major (sg::shadel::buildGpuTables).
#ifndef SG_SHADEL_MARK_LEVELS_GLSL
#define SG_SHADEL_MARK_LEVELS_GLSL

const uint kMarkLevelsLocation = 4u;  // after the alpha test's inputs

struct SgMarkLevel {
  SgLevelRect rect;
  uint sideLog2;     // of the level's owned square, in entries
  uint firstOwned;   // owned-entry index of the level's first entry
};

// levels: level0Size, levelCount, the instance's firstOwnedEntry (and its
// firstLevelRect, not read here); rect: the level's rectangle.
SgMarkLevel sgMarkLevel(uvec4 levels, uint level, SgLevelRect rect) {
  SgMarkLevel l;
  l.rect = rect;
  // Levels above 1 entry: level l' has 4^(k - l') entries while l' < k
  // (k = log2(level0Size / SG_ENTRY_SIZE)), then 1 each.
  int k = max(findMSB(levels.x) - int(SG_ENTRY_SIZE_LOG2), 0);
  uint big = uint(min(int(level), k));  // levels before `level` above one entry
  uint entriesBefore = ((1u << (2u * uint(k) + 2u)) - (1u << (2u * (uint(k) - big) + 2u))) / 3u + (level - big);
  l.sideLog2 = uint(max(k - int(level), 0));
  l.firstOwned = levels.z + entriesBefore;
  return l;
}

// What shadel-clear writes as the storageBase of the remap entry holding
// `shadel` (a shadel of the level): its owned-entry index times the chunk
// slots per entry.
uint sgMarkStorageBase(SgMarkLevel l, uvec2 shadel) {
  uvec2 local = (shadel - l.rect.origin) >> SG_ENTRY_SIZE_LOG2;
  return (l.firstOwned + (local.y << l.sideLog2) + local.x) * SG_CHUNKS_PER_ENTRY;
}

#endif
