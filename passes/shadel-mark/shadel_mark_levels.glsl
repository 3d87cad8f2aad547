// An object's detail levels as shadel-mark's vertex shader hands them to its
// fragment shader (flat), so the fragment shader reads no table for them:
// level 0's size and the level count; per level its origin in remap entries
// and its side in entries (log2), packed x | y << 13 | sideLog2 << 26 (a
// level's origin is a multiple of SG_ENTRY_SIZE in a sheet of at most 2^19
// shadels a side: 13 bits each); and per level the index of its first owned
// entry. A level's size is level0Size >> level (sg::shadel::DetailLevels).
#ifndef SG_SHADEL_MARK_LEVELS_GLSL
#define SG_SHADEL_MARK_LEVELS_GLSL

const uint kMarkLevelsLocation = 4u;                 // after the alpha test's inputs
const uint kMarkLevelVectors = kMaxLevels / 4u;      // four levels per uvec4
const uint kMarkLevelOriginsLocation = kMarkLevelsLocation + 1u;
const uint kMarkLevelOwnedLocation = kMarkLevelOriginsLocation + kMarkLevelVectors;

uint sgPackMarkLevel(SgLevelRect rect) {
  uvec2 entry = rect.origin >> SG_ENTRY_SIZE_LOG2;
  uint sideLog2 = uint(findLSB(rect.allocatedSize >> SG_ENTRY_SIZE_LOG2));
  return entry.x | (entry.y << 13u) | (sideLog2 << 26u);
}

// Entries a level owns: its allocated square, row-major
// (sg::shadel::buildGpuTables lists an instance's owned entries level by level).
uint sgMarkLevelEntries(SgLevelRect rect) {
  uint side = rect.allocatedSize >> SG_ENTRY_SIZE_LOG2;
  return side * side;
}

struct SgMarkLevel {
  SgLevelRect rect;  // allocatedSize left 0: not needed here
  uint sideLog2;     // of the level's allocated square, in entries
  uint firstOwned;   // owned-entry index of the level's first entry
};

SgMarkLevel sgUnpackMarkLevel(uvec4 packed[kMarkLevelVectors], uvec4 owned[kMarkLevelVectors], uvec2 levels,
                              uint level) {
  uint word = packed[level >> 2u][level & 3u];
  SgMarkLevel l;
  l.rect.origin = uvec2(word & 0x1FFFu, (word >> 13u) & 0x1FFFu) << SG_ENTRY_SIZE_LOG2;
  l.rect.size = levels.x >> level;
  l.rect.allocatedSize = 0u;
  l.sideLog2 = word >> 26u;
  l.firstOwned = owned[level >> 2u][level & 3u];
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
