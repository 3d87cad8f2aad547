#include <shadelgraph/gpu/memory.hpp>

#include <algorithm>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/gpu/error.hpp>

namespace sg::gpu {
namespace {
VkDeviceSize alignUp(VkDeviceSize v, VkDeviceSize a) { return (v + a - 1) / a * a; }
}  // namespace

MemoryAllocator::MemoryAllocator(const Context& context, VkDeviceSize blockSize)
    : device_(context.device()), blockSize_(blockSize) {
  vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &properties_);
  // Linear buffers and optimal images may share a block; keeping every range
  // granularity-aligned avoids tracking which is which.
  granularity_ = std::max<VkDeviceSize>(context.properties().limits.bufferImageGranularity, 1);
}

MemoryAllocator::~MemoryAllocator() {
  for (auto& b : blocks_)
    if (b.memory) vkFreeMemory(device_, b.memory, nullptr);
}

uint32_t MemoryAllocator::findMemoryType(uint32_t typeBits, MemoryLocation location) const {
  VkMemoryPropertyFlags want = 0, prefer = 0;
  switch (location) {
    case MemoryLocation::Device: prefer = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT; break;
    case MemoryLocation::Upload:
      want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      break;
    case MemoryLocation::Readback:
      want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
      prefer = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
      break;
  }
  for (VkMemoryPropertyFlags extra : {prefer, VkMemoryPropertyFlags{0}})
    for (uint32_t i = 0; i < properties_.memoryTypeCount; ++i) {
      VkMemoryPropertyFlags f = properties_.memoryTypes[i].propertyFlags;
      if ((typeBits & (1u << i)) && (f & (want | extra)) == (want | extra)) return i;
    }
  throw GpuError("no memory type fits (typeBits " + std::to_string(typeBits) + ")");
}

uint32_t MemoryAllocator::createBlock(uint32_t memoryType, VkDeviceSize size, bool dedicated) {
  VkMemoryAllocateFlagsInfo flags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
  flags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;  // any buffer may want its device address
  VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  info.pNext = &flags;
  info.allocationSize = size;
  info.memoryTypeIndex = memoryType;
  Block block;
  SG_VK(vkAllocateMemory(device_, &info, nullptr, &block.memory));
  block.size = size;
  block.dedicated = dedicated;
  block.memoryType = memoryType;
  block.freeRanges[0] = size;
  if (properties_.memoryTypes[memoryType].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    void* p = nullptr;
    SG_VK(vkMapMemory(device_, block.memory, 0, VK_WHOLE_SIZE, 0, &p));
    block.mapped = static_cast<std::byte*>(p);
  }
  // Reuse a freed slot so block indices held by live allocations stay valid.
  for (uint32_t i = 0; i < blocks_.size(); ++i)
    if (!blocks_[i].memory) {
      blocks_[i] = std::move(block);
      return i;
    }
  blocks_.push_back(std::move(block));
  return static_cast<uint32_t>(blocks_.size() - 1);
}

bool MemoryAllocator::tryPlace(Block& block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize& offset) {
  for (auto it = block.freeRanges.begin(); it != block.freeRanges.end(); ++it) {
    VkDeviceSize start = alignUp(it->first, alignment);
    VkDeviceSize end = it->first + it->second;
    if (start + size > end) continue;
    VkDeviceSize rangeStart = it->first;
    block.freeRanges.erase(it);
    if (start > rangeStart) block.freeRanges[rangeStart] = start - rangeStart;
    if (start + size < end) block.freeRanges[start + size] = end - (start + size);
    offset = start;
    return true;
  }
  return false;
}

Allocation MemoryAllocator::allocate(const VkMemoryRequirements& req, MemoryLocation location, std::string category) {
  std::lock_guard lock(mutex_);
  const uint32_t type = findMemoryType(req.memoryTypeBits, location);
  const VkDeviceSize alignment = std::max(req.alignment, granularity_);
  const VkDeviceSize size = alignUp(req.size, granularity_);
  Allocation a;
  a.memoryType = type;
  a.size = size;
  a.category = std::move(category);
  auto finish = [&](uint32_t index, VkDeviceSize offset) {
    Block& b = blocks_[index];
    a.memory = b.memory;
    a.offset = offset;
    a.block = index;
    a.mapped = b.mapped ? b.mapped + offset : nullptr;
    bytesByCategory_[a.category] += size;
    return a;
  };
  VkDeviceSize offset = 0;
  if (size <= blockSize_ / 2)
    for (uint32_t i = 0; i < blocks_.size(); ++i)
      if (blocks_[i].memory && blocks_[i].memoryType == type && !blocks_[i].dedicated &&
          tryPlace(blocks_[i], size, alignment, offset))
        return finish(i, offset);
  // Large requests get a block of their own, freed with them.
  const bool dedicated = size > blockSize_ / 2;
  const uint32_t index = createBlock(type, dedicated ? size : blockSize_, dedicated);
  if (!tryPlace(blocks_[index], size, alignment, offset)) throw GpuError("memory block too small");
  return finish(index, offset);
}

void MemoryAllocator::free(Allocation& a) {
  if (!a) return;
  std::lock_guard lock(mutex_);
  Block& b = blocks_[a.block];
  bytesByCategory_[a.category] -= a.size;
  if (b.dedicated) {
    vkFreeMemory(device_, b.memory, nullptr);
    b = Block{};
  } else {
    auto [it, inserted] = b.freeRanges.emplace(a.offset, a.size);
    // Coalesce with the following and the preceding free range.
    auto next = std::next(it);
    if (next != b.freeRanges.end() && it->first + it->second == next->first) {
      it->second += next->second;
      b.freeRanges.erase(next);
    }
    if (it != b.freeRanges.begin()) {
      auto prev = std::prev(it);
      if (prev->first + prev->second == it->first) {
        prev->second += it->second;
        b.freeRanges.erase(it);
      }
    }
  }
  a = Allocation{};
}

MemoryTotals MemoryAllocator::totals() const {
  std::lock_guard lock(mutex_);
  MemoryTotals t;
  for (auto& [k, v] : bytesByCategory_)
    if (v) t.bytesByCategory[k] = v;
  for (auto& b : blocks_)
    if (b.memory) {
      t.reservedBytes += b.size;
      ++t.blockCount;
    }
  return t;
}

}  // namespace sg::gpu
