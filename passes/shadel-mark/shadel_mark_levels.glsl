// An object's detail levels as shadel-mark's vertex shader hands them to its
// fragment shader (flat), so the fragment shader reads no table for them:
// level 0's size, the level count and the instance's first owned entry; per
// level its origin in remap entries, packed x | y << 13 (a level's origin is
// a multiple of SG_ENTRY_SIZE in a sheet of at most 2^19 shadels a side). The
// rest follows from level 0's size (sg::shadel::DetailLevels, ShadelSpace):
// a level is level0Size >> level shadels a side and owns a square of
// max(size / SG_ENTRY_SIZE, 1) entries a side, listed level by level,
// row-major (sg::shadel::buildGpuTables).
#ifndef SG_SHADEL_MARK_LEVELS_GLSL
#define SG_SHADEL_MARK_LEVELS_GLSL

const uint kMarkLevelsLocation = 4u;                 // after the alpha test's inputs
const uint kMarkLevelVectors = kMaxLevels / 4u;      // four levels per uvec4
const uint kMarkLevelOriginsLocation = kMarkLevelsLocation + 1u;

uint sgPackMarkOrigin(uvec2 origin) {
  uvec2 entry = origin >> SG_ENTRY_SIZE_LOG2;
  return entry.x | (entry.y << 13u);
}

struct SgMarkLevel {
  SgLevelRect rect;  // allocatedSize left 0: not needed here
  uint sideLog2;     // of the level's owned square, in entries
  uint firstOwned;   // owned-entry index of the level's first entry
};

// levels: level0Size, levelCount, the instance's firstOwnedEntry.
SgMarkLevel sgUnpackMarkLevel(uvec4 origins[kMarkLevelVectors], uvec3 levels, uint level) {
  uint word = origins[level >> 2u][level & 3u];
  SgMarkLevel l;
  l.rect.origin = uvec2(word & 0x1FFFu, word >> 13u) << SG_ENTRY_SIZE_LOG2;
  l.rect.size = levels.x >> level;
  l.rect.allocatedSize = 0u;
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
