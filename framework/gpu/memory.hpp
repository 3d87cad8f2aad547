#pragma once
// A sub-allocator for device memory (Debian ships no VMA): large blocks per
// memory type, first-fit ranges with coalescing, and running totals per
// category so the application can report where its memory went.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace sg::gpu {

class Context;

// Where the memory should live.
enum class MemoryLocation { Device, Upload, Readback };

struct Allocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
  std::byte* mapped = nullptr;  // non-null for host-visible memory
  uint32_t memoryType = 0;
  uint32_t block = UINT32_MAX;
  std::string category;
  explicit operator bool() const { return memory != VK_NULL_HANDLE; }
};

struct MemoryTotals {
  std::map<std::string, VkDeviceSize> bytesByCategory;  // live sub-allocations
  VkDeviceSize reservedBytes = 0;                       // VkDeviceMemory blocks
  uint32_t blockCount = 0;
};

class MemoryAllocator {
 public:
  explicit MemoryAllocator(const Context& context, VkDeviceSize blockSize = 64ull << 20);
  ~MemoryAllocator();
  MemoryAllocator(const MemoryAllocator&) = delete;
  MemoryAllocator& operator=(const MemoryAllocator&) = delete;

  Allocation allocate(const VkMemoryRequirements& requirements, MemoryLocation location, std::string category);
  void free(Allocation& allocation);
  MemoryTotals totals() const;

 private:
  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    uint32_t memoryType = 0;
    std::byte* mapped = nullptr;
    bool dedicated = false;  // holds one allocation, freed with it
    std::map<VkDeviceSize, VkDeviceSize> freeRanges;  // offset -> size
  };
  uint32_t findMemoryType(uint32_t typeBits, MemoryLocation location) const;
  uint32_t createBlock(uint32_t memoryType, VkDeviceSize size, bool dedicated);
  bool tryPlace(Block& block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize& offset);

  VkDevice device_;
  VkPhysicalDeviceMemoryProperties properties_{};
  VkDeviceSize blockSize_;
  VkDeviceSize granularity_;
  mutable std::mutex mutex_;
  std::vector<Block> blocks_;
  std::map<std::string, VkDeviceSize> bytesByCategory_;
};

}  // namespace sg::gpu
