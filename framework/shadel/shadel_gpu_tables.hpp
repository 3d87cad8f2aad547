#pragma once
// The ShadelSpace as flat arrays for upload (std430 records, mirrored in
// shaders/shadel_address.glsl). Rebuild when ShadelSpace::generation()
// changes.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <shadelgraph/shadel/level_rect.hpp>
#include <shadelgraph/shadel/shadel_space.hpp>

namespace sg::shadel {

// Per instance id: where its level rectangles are in levelRects. GLSL: SgShadelInstance.
struct GpuShadelInstance {
  uint32_t firstLevelRect = 0;
  uint32_t levelCount = 0;  // 0: the id has no shadel space (not allocated)
  uint32_t level0Size = 0;
  uint32_t firstOwnedEntry = 0;  // its run in ownedEntries
};
static_assert(sizeof(GpuShadelInstance) == 16);

// One remap entry some instance owns. shadel-clear runs over this list (cost
// proportional to allocated entries, not to the sheet), resetting each entry
// to {kNoStorage, instanceId, 0}; work-aggregate can use `level` to tag work
// items. GLSL: SgOwnedEntry.
struct OwnedEntry {
  uint32_t entryIndex = 0;
  uint32_t instanceId = kNoInstance;
  uint32_t level = 0;
  uint32_t reserved = 0;
};
static_assert(sizeof(OwnedEntry) == 16);
static_assert(offsetof(OwnedEntry, level) == 8);

struct ShadelGpuTables {
  std::vector<GpuShadelInstance> instances;  // indexed by instance id, up to the largest allocated id
  std::vector<LevelRect> levelRects;
  std::vector<OwnedEntry> ownedEntries;      // grouped by instance, ascending id, then by level
  uint64_t generation = 0;                   // ShadelSpace::generation() they were built from
};

ShadelGpuTables buildGpuTables(const ShadelSpace& space);

}  // namespace sg::shadel
