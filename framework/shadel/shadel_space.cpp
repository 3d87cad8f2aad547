#include <algorithm>
#include <bit>
#include <stdexcept>

#include <shadelgraph/shadel/shadel_space.hpp>

namespace sg::shadel {
namespace {

// A level's square in remap entries: its size snapped up to one entry.
uint32_t entriesLog2For(uint32_t levelSize) {
  const uint32_t entries = std::max(levelSize / kEntrySize, 1u);
  return static_cast<uint32_t>(std::countr_zero(entries));
}

AllocationResult failure(AllocationError error, std::string message) {
  return {error, std::move(message), nullptr};
}

uint32_t checkedSheetSizeLog2(const ShadelSpaceConfig& config) {
  if (config.sheetSizeLog2 < kMinSheetSizeLog2 || config.sheetSizeLog2 > kMaxSheetSizeLog2)
    throw std::invalid_argument("ShadelSpace: sheet size 2^" + std::to_string(config.sheetSizeLog2) +
                                " outside 2^16 (64K) .. 2^19 (512K) shadels");
  return config.sheetSizeLog2;
}

}  // namespace

uint64_t InstanceShadels::entryCount() const {
  uint64_t count = 0;
  for (const QuadtreeAllocator::Block& block : blocks) count += uint64_t{1} << (2 * block.sizeLog2);
  return count;
}

ShadelSpace::ShadelSpace(const ShadelSpaceConfig& config)
    : geometry_{checkedSheetSizeLog2(config)}, allocator_(geometry_.entriesPerSideLog2()) {}

AllocationResult ShadelSpace::allocate(uint32_t instanceId, const DetailLevels& levels) {
  const std::string who = "instance " + std::to_string(instanceId);
  if (instanceId == kNoInstance || instanceId > kMaxInstanceId)
    return failure(AllocationError::InvalidInstanceId, who + ": ids must be below 2^24");
  if (!levels.valid())
    return failure(AllocationError::InvalidLevels, who + ": invalid detail levels (level 0 " +
                                                       std::to_string(levels.level0Size) + ", " +
                                                       std::to_string(levels.levelCount) + " levels)");
  if (instances_.count(instanceId)) return failure(AllocationError::DuplicateInstance, who + " is already allocated");

  InstanceShadels instance;
  instance.instanceId = instanceId;
  instance.levels = levels;
  for (uint32_t level = 0; level < levels.levelCount; ++level) {
    const uint32_t size = levels.levelSize(level);
    const std::optional<QuadtreeAllocator::Block> block = allocator_.allocate(entriesLog2For(size));
    if (!block) {
      for (const QuadtreeAllocator::Block& taken : instance.blocks) allocator_.release(taken);
      return failure(AllocationError::OutOfSpace,
                     who + ": no free " + std::to_string(std::max(size, kEntrySize)) + "² shadel square for level " +
                         std::to_string(level) + " (" + std::to_string(freeEntries()) + " of " +
                         std::to_string(allocator_.totalCells()) + " remap entries free)");
    }
    instance.blocks.push_back(*block);
    instance.rects.push_back({block->origin * kEntrySize, size, kEntrySize << block->sizeLog2});
  }
  ++generation_;
  const auto [it, inserted] = instances_.emplace(instanceId, std::move(instance));
  return {AllocationError::None, {}, &it->second};
}

bool ShadelSpace::release(uint32_t instanceId) {
  const auto it = instances_.find(instanceId);
  if (it == instances_.end()) return false;
  for (const QuadtreeAllocator::Block& block : it->second.blocks) allocator_.release(block);
  instances_.erase(it);
  ++generation_;
  return true;
}

const InstanceShadels* ShadelSpace::find(uint32_t instanceId) const {
  const auto it = instances_.find(instanceId);
  return it == instances_.end() ? nullptr : &it->second;
}

std::vector<uint32_t> ShadelSpace::ownedEntries(uint32_t instanceId) const {
  std::vector<uint32_t> entries;
  const InstanceShadels* instance = find(instanceId);
  if (!instance) return entries;
  entries.reserve(instance->entryCount());
  const uint32_t log2 = geometry_.entriesPerSideLog2();
  for (const QuadtreeAllocator::Block& block : instance->blocks) {
    const uint32_t side = 1u << block.sizeLog2;
    for (uint32_t y = 0; y < side; ++y)
      for (uint32_t x = 0; x < side; ++x) entries.push_back(((block.origin.y + y) << log2) | (block.origin.x + x));
  }
  return entries;
}

const char* toString(AllocationError error) {
  switch (error) {
    case AllocationError::None: return "none";
    case AllocationError::OutOfSpace: return "out of space";
    case AllocationError::DuplicateInstance: return "duplicate instance";
    case AllocationError::InvalidInstanceId: return "invalid instance id";
    case AllocationError::InvalidLevels: return "invalid detail levels";
  }
  return "?";
}

}  // namespace sg::shadel
