// Virtual shadel sheet addressing: the GLSL twin of
// framework/shadel/remap_entry.hpp, shadel_address.hpp, level_rect.hpp and
// shadel_gpu_tables.hpp. Same integer math, function for function; each
// function names the C++ one it mirrors, and the unit/device tests check them
// against each other (tests/unit/shadel/glsl_mirror_*).
//
// Needs GL_EXT_shader_explicit_arithmetic_types_int64 (uint64_t occupancy;
// the device enables shaderInt64). shadel-mark sets bits with
// atomicOr(remap[i].occupancy, sgChunkBit(c)) (GL_EXT_shader_atomic_int64,
// shaderBufferInt64Atomics), after a plain read shows the bit unset.
#ifndef SG_SHADEL_ADDRESS_GLSL
#define SG_SHADEL_ADDRESS_GLSL

#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

// remap_entry.hpp constants.
const uint SG_CHUNK_SIZE = 8u;
const uint SG_CHUNK_SIZE_LOG2 = 3u;
const uint SG_ENTRY_CHUNKS = 8u;
const uint SG_ENTRY_SIZE = 64u;
const uint SG_ENTRY_SIZE_LOG2 = 6u;
const uint SG_CHUNKS_PER_ENTRY = 64u;
const uint SG_STORED_CHUNK_SIZE = 9u;  // a chunk's tile in storage: 8x8 and a one-shadel gutter right and below
const uint SG_NO_STORAGE = 0xFFFFFFFFu;
const uint SG_NO_INSTANCE = 0xFFFFFFFFu;
const uint SG_INVALID_CHUNK = 0xFFFFFFFFu;

// sg::shadel::RemapEntry (16 bytes, std430).
struct SgRemapEntry {
  uint storageBase;
  uint objectInstanceId;
  uint64_t occupancy;
};

// sg::shadel::LevelRect (16 bytes, std430).
struct SgLevelRect {
  uvec2 origin;
  uint size;
  uint allocatedSize;
};

// sg::shadel::GpuShadelInstance (16 bytes, std430).
struct SgShadelInstance {
  uint firstLevelRect;
  uint levelCount;
  uint level0Size;
  uint firstOwnedEntry;
};

// sg::shadel::OwnedEntry (16 bytes, std430).
struct SgOwnedEntry {
  uint entryIndex;
  uint instanceId;
  uint level;
  uint reserved;
};

// Where level `level` of an instance is in the level-rectangle array
// (sg::shadel::buildGpuTables puts each instance's levels in a run).
uint sgLevelRectIndex(SgShadelInstance instance, uint level) { return instance.firstLevelRect + level; }

// sg::shadel::ShadelAddress.
struct SgShadelAddress {
  uint entryIndex;  // entryY * entriesPerSide + entryX
  uint chunkIndex;  // chunkY * 8 + chunkX inside the entry: the occupancy bit
  uint texelIndex;  // texelY * 8 + texelX inside the chunk
};

// Mirrors sg::shadel::addressOf.
SgShadelAddress sgShadelAddress(uvec2 shadel, uint entriesPerSideLog2) {
  uvec2 entry = shadel >> SG_ENTRY_SIZE_LOG2;
  uvec2 chunk = (shadel >> SG_CHUNK_SIZE_LOG2) & (SG_ENTRY_CHUNKS - 1u);
  uvec2 texel = shadel & (SG_CHUNK_SIZE - 1u);
  return SgShadelAddress((entry.y << entriesPerSideLog2) | entry.x, chunk.y * SG_ENTRY_CHUNKS + chunk.x,
                         texel.y * SG_CHUNK_SIZE + texel.x);
}

// Mirrors sg::shadel::virtualShadelOf.
uvec2 sgVirtualShadel(SgShadelAddress address, uint entriesPerSideLog2) {
  uvec2 entry = uvec2(address.entryIndex & ((1u << entriesPerSideLog2) - 1u), address.entryIndex >> entriesPerSideLog2);
  uvec2 chunk = uvec2(address.chunkIndex & (SG_ENTRY_CHUNKS - 1u), address.chunkIndex >> 3u);
  uvec2 texel = uvec2(address.texelIndex & (SG_CHUNK_SIZE - 1u), address.texelIndex >> 3u);
  return (entry << SG_ENTRY_SIZE_LOG2) | (chunk << SG_CHUNK_SIZE_LOG2) | texel;
}

// The occupancy bit of a chunk (for atomicOr in shadel-mark).
uint64_t sgChunkBit(uint chunkIndex) { return uint64_t(1u) << chunkIndex; }

// Mirrors sg::shadel::chunksBefore: popcount of the bits below chunkIndex,
// as two 32-bit bitCounts.
uint sgChunksBefore(uint64_t occupancy, uint chunkIndex) {
  uvec2 bits = unpackUint2x32(occupancy & (sgChunkBit(chunkIndex) - uint64_t(1u)));
  return uint(bitCount(bits.x) + bitCount(bits.y));
}

// Mirrors sg::shadel::isChunkMarked.
bool sgIsChunkMarked(uint64_t occupancy, uint chunkIndex) { return ((occupancy >> chunkIndex) & uint64_t(1u)) != uint64_t(0u); }

// Mirrors sg::shadel::physicalChunk: SG_INVALID_CHUNK when the chunk is not
// marked or its entry got no storage.
uint sgPhysicalChunk(SgRemapEntry entry, uint chunkIndex) {
  if (!sgIsChunkMarked(entry.occupancy, chunkIndex) || entry.storageBase == SG_NO_STORAGE) return SG_INVALID_CHUNK;
  return entry.storageBase + sgChunksBefore(entry.occupancy, chunkIndex);
}

// Mirrors sg::shadel::storedTexel: texel `inTile` (in [0,9)², 8 = the
// gutter) of a physical chunk's tile in a layer image.
uvec2 sgStoredTexel(uint physicalChunk, uvec2 inTile, uint widthChunks) {
  uvec2 chunk = uvec2(physicalChunk % widthChunks, physicalChunk / widthChunks);
  return chunk * SG_STORED_CHUNK_SIZE + inTile;
}

// Shadel texelIndex (8x8 row-major) of a chunk as (column, row).
uvec2 sgTexelInChunk(uint texelIndex) { return uvec2(texelIndex & (SG_CHUNK_SIZE - 1u), texelIndex >> 3u); }

// Mirrors sg::shadel::storageTexel: the texel of shadel texelIndex (8x8 row-major) of a physical chunk.
uvec2 sgStorageTexel(uint physicalChunk, uint texelIndex, uint widthChunks) {
  return sgStoredTexel(physicalChunk, sgTexelInChunk(texelIndex), widthChunks);
}

// Mirrors sg::shadel::storageCounterFor: the allocation counter (storage
// partition) shadel-allocate uses for an entry.
uint sgStorageCounter(uint entryIndex, uint counterCount) {
  uint h = entryIndex;
  h ^= h >> 16u;
  h *= 0x7feb352du;
  h ^= h >> 15u;
  h *= 0x846ca68bu;
  h ^= h >> 16u;
  return h % counterCount;
}

#endif
