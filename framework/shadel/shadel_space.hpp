#pragma once
// The virtual shadel sheet on the CPU side: which instance owns which part.
//
// Each object instance that may render gets one square rectangle per detail
// level (paper §3.3: sized by its maximum needed density, the small levels
// snapped up to a minimum block), freed when the instance leaves. Space is
// handed out in whole remap entries (64x64 shadels) by a buddy quadtree
// (quadtree_allocator.hpp), so instances never share an entry: an entry's
// objectInstanceId is well defined and a level's shadels never alias another
// instance's.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <shadelgraph/shadel/detail_levels.hpp>
#include <shadelgraph/shadel/level_rect.hpp>
#include <shadelgraph/shadel/quadtree_allocator.hpp>
#include <shadelgraph/shadel/shadel_address.hpp>

namespace sg::shadel {

inline constexpr uint32_t kMinSheetSizeLog2 = 16;  // 64K x 64K shadels
inline constexpr uint32_t kMaxSheetSizeLog2 = 19;  // 512K x 512K shadels
// Instance ids index the GPU instance table (shadel_gpu_tables.hpp): keep them dense.
inline constexpr uint32_t kMaxInstanceId = (1u << 24) - 1;

struct ShadelSpaceConfig {
  uint32_t sheetSizeLog2 = 16;  // kMinSheetSizeLog2..kMaxSheetSizeLog2
};

// One allocated instance.
struct InstanceShadels {
  uint32_t instanceId = kNoInstance;
  DetailLevels levels;
  std::vector<LevelRect> rects;                        // one per level, level 0 first
  std::vector<QuadtreeAllocator::Block> blocks;        // the same, in remap entries

  uint64_t entryCount() const;
};

enum class AllocationError {
  None,
  OutOfSpace,         // no free square large enough for some level: free instances or use a larger sheet
  DuplicateInstance,  // the id is already allocated
  InvalidInstanceId,  // kNoInstance or above kMaxInstanceId
  InvalidLevels,      // DetailLevels::valid() is false
};

struct AllocationResult {
  AllocationError error = AllocationError::None;
  std::string message;                        // one line for people; empty on success
  const InstanceShadels* instance = nullptr;  // on success; valid until the instance is released

  bool ok() const { return error == AllocationError::None; }
};

class ShadelSpace {
 public:
  // Throws std::invalid_argument for a sheet size outside the supported range.
  explicit ShadelSpace(const ShadelSpaceConfig& config = {});

  // All levels or none: on failure nothing stays allocated.
  AllocationResult allocate(uint32_t instanceId, const DetailLevels& levels);
  // False when the id is not allocated.
  bool release(uint32_t instanceId);

  const InstanceShadels* find(uint32_t instanceId) const;
  const std::map<uint32_t, InstanceShadels>& instances() const { return instances_; }

  // Remap-entry indices (into the dense table) the instance owns, level by
  // level, row-major inside each level: what shadel-clear must reset.
  std::vector<uint32_t> ownedEntries(uint32_t instanceId) const;

  SheetGeometry geometry() const { return geometry_; }
  uint64_t allocatedEntries() const { return allocator_.totalCells() - allocator_.freeCells(); }
  uint64_t freeEntries() const { return allocator_.freeCells(); }
  // Bumped by every successful allocate and release: re-upload GPU tables when it changes.
  uint64_t generation() const { return generation_; }

 private:
  SheetGeometry geometry_;
  QuadtreeAllocator allocator_;
  std::map<uint32_t, InstanceShadels> instances_;
  uint64_t generation_ = 0;
};

const char* toString(AllocationError error);

}  // namespace sg::shadel
