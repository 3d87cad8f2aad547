#include "chunk_slots.hpp"

#include <algorithm>
#include <cstring>

#include <shadelgraph/shadel/remap_entry.hpp>
#include <shadelgraph/shadel/shaders/decoupled_interface.h>

namespace sg::plugins {
namespace {
constexpr uint32_t kPerEntry = shadel::kChunksPerEntry;

constexpr uint32_t kMaskWords = 4;  // per owned entry: the stored and fresh masks (chunk_slots.glsl)
// The slots, the masks, the free count and stack.
uint64_t bufferWords(size_t ownedEntries, uint32_t capacity) {
  return uint64_t(ownedEntries) * (kPerEntry + kMaskWords) + 1 + capacity;
}
}  // namespace

void ChunkSlots::setOwnedEntries(std::vector<shadel::OwnedEntry> owned) {
  if (valid_ && !previous_) previous_ = std::move(owned_);
  owned_ = std::move(owned);
  valid_ = false;
}

std::vector<uint32_t> ChunkSlots::carriedOver(const std::vector<uint32_t>& old) const {
  const auto& before = *previous_;
  std::vector<uint32_t> slots(bufferWords(owned_.size(), capacity_), shader::kNoSlot);
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> oldIndex;  // (entry, instance) -> old owned index
  for (uint32_t j = 0; j < before.size(); ++j) oldIndex[{before[j].entryIndex, before[j].instanceId}] = j;
  std::vector<bool> carried(before.size(), false);
  for (size_t i = 0; i < owned_.size(); ++i)  // nothing stored, nothing fresh
    std::fill_n(&slots[owned_.size() * kPerEntry + i * kMaskWords], kMaskWords, 0u);
  for (uint32_t i = 0; i < owned_.size(); ++i) {
    const auto it = oldIndex.find({owned_[i].entryIndex, owned_[i].instanceId});
    if (it == oldIndex.end()) continue;
    carried[it->second] = true;
    std::memcpy(&slots[size_t(i) * kPerEntry], &old[size_t(it->second) * kPerEntry], kPerEntry * sizeof(uint32_t));
    std::memcpy(&slots[owned_.size() * kPerEntry + size_t(i) * kMaskWords],
                &old[before.size() * kPerEntry + size_t(it->second) * kMaskWords], kMaskWords * sizeof(uint32_t));
  }
  // The free list as it was, plus the storage of entries no one owns any more.
  const size_t oldCount = before.size() * (kPerEntry + kMaskWords), newCount = owned_.size() * (kPerEntry + kMaskWords);
  uint32_t free = old[oldCount];
  std::memcpy(&slots[newCount + 1], &old[oldCount + 1], size_t(free) * sizeof(uint32_t));
  for (uint32_t j = 0; j < before.size(); ++j)
    if (!carried[j])
      for (uint32_t c = 0; c < kPerEntry; ++c)
        if (const uint32_t slot = old[size_t(j) * kPerEntry + c]; slot != shader::kNoSlot)
          slots[newCount + 1 + free++] = slot;
  slots[newCount] = free;
  return slots;
}

void ChunkSlots::prepare(gpu::Device& device, gpu::GraphExecutor& executor, uint32_t capacityChunks) {
  const uint64_t bytes = bufferWords(owned_.size(), capacityChunks) * sizeof(uint32_t);
  if (valid_ && buffer_.size() == bytes && capacity_ == capacityChunks) return;
  executor.finish();  // a frame in flight may still use the old slots
  std::vector<uint32_t> carried;
  if (previous_ && buffer_ && capacity_ == capacityChunks) carried = carriedOver(read(device));
  previous_.reset();
  capacity_ = capacityChunks;
  if (!buffer_ || buffer_.size() != bytes)
    buffer_ = gpu::Buffer(device.context(), device.memory(),
                          {bytes,
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                               VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,  // texels: composite
                           gpu::MemoryLocation::Device, "chunk slots", "remap", /*concurrent*/ true});
  if (carried.empty()) {
    // Start over on the host (a frame may be planned and never run, so the reset cannot wait for one):
    // every slot empty, no masks, every chunk on the free list, chunk 0 on top.
    const size_t count = owned_.size() * (kPerEntry + kMaskWords);
    carried.assign(bufferWords(owned_.size(), capacity_), shader::kNoSlot);
    std::fill_n(&carried[owned_.size() * kPerEntry], owned_.size() * kMaskWords, 0u);
    carried[count] = capacity_;
    for (uint32_t i = 0; i < capacity_; ++i) carried[count + 1 + i] = capacity_ - 1 - i;
  }
  write(device, carried);
  valid_ = true;
}

std::vector<uint32_t> ChunkSlots::read(gpu::Device& device) const {
  gpu::Buffer host(device.context(), device.memory(),
                   {buffer_.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Readback,
                    "chunk slots readback", "readback"});
  device.context().submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, buffer_.size()};
    vkCmdCopyBuffer(cmd, buffer_.handle(), host.handle(), 1, &region);
  });
  std::vector<uint32_t> slots(buffer_.size() / sizeof(uint32_t));
  std::memcpy(slots.data(), host.mapped(), slots.size() * sizeof(uint32_t));
  return slots;
}

void ChunkSlots::write(gpu::Device& device, const std::vector<uint32_t>& slots) {
  const uint64_t bytes = slots.size() * sizeof(uint32_t);
  gpu::Buffer host(device.context(), device.memory(),
                   {bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryLocation::Upload, "chunk slots upload",
                    "decoupled tables"});
  host.write(slots.data(), bytes);
  device.context().submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, bytes};
    vkCmdCopyBuffer(cmd, host.handle(), buffer_.handle(), 1, &region);
  });
}

std::map<uint64_t, uint32_t> ChunkSlots::addresses(gpu::Device& device) const {
  std::map<uint64_t, uint32_t> out;
  if (!buffer_) return out;
  const std::vector<uint32_t> slots = read(device);
  for (uint32_t i = 0; i < owned_.size(); ++i)
    for (uint32_t c = 0; c < kPerEntry; ++c)
      if (const uint32_t slot = slots[size_t(i) * kPerEntry + c]; slot != shader::kNoSlot)
        out[uint64_t(owned_[i].entryIndex) * kPerEntry + c] = slot;
  return out;
}

}  // namespace sg::plugins
