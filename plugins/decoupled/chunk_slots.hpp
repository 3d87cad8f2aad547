#pragma once
// Stable allocation (issue 15), the host's side: the GPU buffer of chunk slots
// and free list that shadel-allocate keeps from frame to frame
// (framework/shadel/shaders/chunk_slots.glsl). Its layout follows the owned
// remap entries; when they change (an object gets or gives back shadel
// space), the slots of entries that stay are carried over, on the host, to
// their new places and the others freed, so the rest of the scene keeps its
// storage. Only another storage capacity starts over (written on the host).
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/shadel/shadel_gpu_tables.hpp>

namespace sg::plugins {

class ChunkSlots {
 public:
  // New owned entries (uploadTables): the slots move with them at the next prepare.
  void setOwnedEntries(std::vector<shadel::OwnedEntry> owned);
  // Before a frame that allocates: the buffer for `capacityChunks` of storage,
  // its slots carried over or reset here on the host.
  void prepare(gpu::Device& device, gpu::GraphExecutor& executor, uint32_t capacityChunks);
  const gpu::Buffer& buffer() const { return buffer_; }
  uint64_t bytes() const { return buffer_ ? buffer_.size() : 0; }
  // Entry index * 64 + chunk -> physical chunk, of every chunk with storage (after a completed frame).
  std::map<uint64_t, uint32_t> addresses(gpu::Device& device) const;

 private:
  std::vector<uint32_t> read(gpu::Device& device) const;
  void write(gpu::Device& device, const std::vector<uint32_t>& slots);
  // The buffer's content laid out for owned_, from `old` laid out for previous_.
  std::vector<uint32_t> carriedOver(const std::vector<uint32_t>& old) const;

  gpu::Buffer buffer_;
  bool valid_ = false;
  uint32_t capacity_ = 0;
  std::vector<shadel::OwnedEntry> owned_;
  std::optional<std::vector<shadel::OwnedEntry>> previous_;  // the layout the buffer still has
};

}  // namespace sg::plugins
