#pragma once
// The virtual shadel sheet's geometry constants and its one GPU record, the
// remap entry (Baker & Jarzynski 2022, §3.3).
//
// Shadels live in 8x8 chunks; one remap entry covers 8x8 chunks (64x64
// shadels) and says where its marked chunks are stored: chunk c of the entry
// is at storageBase + popcount(occupancy & ((1 << c) - 1)), so a lookup is one
// dependent read. The remap table is dense over the sheet (entry index =
// entryY * entriesPerSide + entryX), like the paper's 2D remap texture: at
// 16 bytes an entry it costs 16 MiB for a 64K² sheet, 64 MiB for 128K²,
// 256 MiB for 256K², 1 GiB for 512K².
#include <cstddef>
#include <cstdint>

namespace sg::shadel {

inline constexpr uint32_t kChunkSize = 8;             // shadels per chunk side
inline constexpr uint32_t kChunkSizeLog2 = 3;
inline constexpr uint32_t kEntryChunks = 8;           // chunks per remap entry side
inline constexpr uint32_t kEntrySize = 64;            // shadels per remap entry side
inline constexpr uint32_t kEntrySizeLog2 = 6;
inline constexpr uint32_t kChunksPerEntry = 64;       // one occupancy bit each
inline constexpr uint32_t kShadelsPerChunk = 64;
// A chunk's tile in shade storage: its 8x8 shadels plus a one-shadel gutter
// right and below, a copy of the next chunks' first column and row
// (passes/shadel-gutter), so a bilinear footprint whose top-left tap is in
// the chunk never leaves its tile: composite needs one remap lookup per level.
inline constexpr uint32_t kStoredChunkSize = kChunkSize + 1;

// RemapEntry::storageBase of an entry that got no storage (never marked, or
// the allocator's partition overflowed).
inline constexpr uint32_t kNoStorage = 0xFFFFFFFFu;
// RemapEntry::objectInstanceId of an entry no instance owns.
inline constexpr uint32_t kNoInstance = 0xFFFFFFFFu;
// What a lookup of an unmarked (or unstored) chunk returns.
inline constexpr uint32_t kInvalidChunk = 0xFFFFFFFFu;

// std430 layout, mirrored by SgRemapEntry in shaders/shadel_address.glsl.
struct RemapEntry {
  uint32_t storageBase = kNoStorage;       // first physical chunk of this entry's marked chunks
  uint32_t objectInstanceId = kNoInstance;  // owner, written when the instance is allocated
  uint64_t occupancy = 0;                   // bit c: chunk c (= chunkY * 8 + chunkX) is marked
};
static_assert(sizeof(RemapEntry) == 16);
static_assert(alignof(RemapEntry) == 8);
static_assert(offsetof(RemapEntry, storageBase) == 0);
static_assert(offsetof(RemapEntry, objectInstanceId) == 4);
static_assert(offsetof(RemapEntry, occupancy) == 8);

}  // namespace sg::shadel
