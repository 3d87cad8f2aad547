#pragma once

#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/graph/memory_requirements.hpp>
#include <shadelgraph/graph/graph_declaration.hpp>
#include <shadelgraph/graph/queue.hpp>
#include <shadelgraph/graph/range.hpp>
#include <shadelgraph/graph/resource_desc.hpp>
#include <shadelgraph/graph/sync_types.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sg::graph {

// A synchronization2 barrier in graph terms (image barrier when the resource is
// an image, buffer barrier otherwise; buffers keep both layouts Undefined).
struct Barrier {
  ResourceId resource;
  PipelineStage srcStages = PipelineStage::None;
  PipelineStage dstStages = PipelineStage::None;
  AccessFlag srcAccess = AccessFlag::None;
  AccessFlag dstAccess = AccessFlag::None;
  Layout oldLayout = Layout::Undefined;
  Layout newLayout = Layout::Undefined;
  // The previous contents are not needed (oldLayout is Undefined): first use of
  // a transient, an import declared Undefined, or memory taken over from aliased transients.
  bool discard = false;
  friend bool operator==(const Barrier&, const Barrier&) = default;
};

// Wait until the timeline semaphore of `queue` reaches `value`, blocking `dstStages`.
struct SemaphoreWait {
  QueueClass queue = QueueClass::Graphics;
  uint64_t value = 0;
  PipelineStage dstStages = PipelineStage::None;
  friend bool operator==(const SemaphoreWait&, const SemaphoreWait&) = default;
};

// Consecutive passes (in execution order) on one logical queue: one submission.
// Timeline values count a queue's batches from 1 within the frame; the executor
// adds its per-frame base so values keep increasing across frames.
struct Batch {
  QueueClass queue = QueueClass::Graphics;
  Range passes;  // into CompiledPlan::order: batches are consecutive runs of it
  Range waits;   // into CompiledPlan::waits
  uint64_t signalValue = 0;  // signalled at the end of the batch; 0 when nobody waits on it
  // Runs past the frame: none of the frame's results needs it, only later
  // frames (through persistent resources); the host does not wait for it.
  bool tail = false;
};

// The first and last batch using an external (imported, persistent, history)
// resource on one logical queue, and the stages of that first use: where the
// frame orders itself after earlier frames' uses of the same memory on other
// queues (frame_boundary.hpp).
struct ExternalUse {
  ResourceId resource;
  QueueClass queue = QueueClass::Graphics;
  uint32_t firstBatch = kInvalidIndex;
  uint32_t lastBatch = kInvalidIndex;
  PipelineStage firstStages = PipelineStage::None;
  friend bool operator==(const ExternalUse&, const ExternalUse&) = default;
};

// Leaves an external resource in its declared final state. Recorded right after
// pass `afterPass` (in `batch`); afterPass is invalid only when no pass runs at all.
struct FinalBarrier {
  Barrier barrier;
  PassId afterPass;
  uint32_t batch = kInvalidIndex;
};

// Where a transient lives: a byte range of one heap (one VkDeviceMemory).
struct MemoryPlacement {
  uint32_t heap = kInvalidIndex;
  uint64_t offset = 0;
  uint64_t size = 0;
  bool placed() const { return heap != kInvalidIndex; }
  friend bool operator==(const MemoryPlacement&, const MemoryPlacement&) = default;
};

struct Heap {
  uint32_t memoryTypeBits = ~uint32_t{0};  // allocate from any memory type in this set
  uint64_t size = 0;
  uint64_t alignment = 1;
  QueueMask queues = QueueMask::None;  // the queue(s) its transients are used on
  bool aliasing = false;               // transients in it share memory
};

// (Fields the compile steps read most come first: they share a cache line.)
struct PlannedResource {
  ResourceKind kind = ResourceKind::TransientImage;
  bool culled = false;  // no kept pass touches it; the executor need not create it
  bool readOnly = false;
  ResourceId historyOf;  // History: its persistent resource
  // Positions in CompiledPlan::order of the first and last kept pass using it.
  uint32_t firstUse = kInvalidIndex;
  uint32_t lastUse = kInvalidIndex;
  // Transients whose memory this one takes over directly, or which take over
  // its memory (into CompiledPlan::aliases; see aliasesOf()).
  Range aliasesWith;
  MemoryPlacement memory;  // transients
  ResourceDesc desc;       // type, resolved size, usage, queues, concurrent
  MemoryRequirements requirements;  // transients
  ResourceState initialState;  // external kinds: state at frame start
  ResourceState finalState;    // external kinds: state to leave it in
  std::string name;
};

struct PlannedPass {
  std::string name;
  QueueClass queue = QueueClass::Graphics;
  PassKind kind = PassKind::Raster;
  bool sideEffect = false;
  bool culled = false;
  Range accesses;        // into CompiledPlan::accesses
  Range barriersBefore;  // into CompiledPlan::barriers
  // Layout hand-offs done on this queue for readers on other queues (see docs).
  Range barriersAfter;   // into CompiledPlan::barriers
  uint32_t batch = kInvalidIndex;
  uint32_t orderIndex = kInvalidIndex;  // position in CompiledPlan::order
};

// The compiled frame: plain data. passes[i] is graph.pass(PassId{i}); the
// executor invokes that pass's callback. Executing a batch: wait waitsOf(batch),
// then for each pass of passesOf(batch) record barriersBefore(p), the callback,
// barriersAfter(p) and the final barriers whose afterPass is p; then signal
// signalValue if non-zero.
struct CompiledPlan {
  uint32_t outputWidth = 0;
  uint32_t outputHeight = 0;
  std::vector<PlannedResource> resources;  // indexed by ResourceId
  std::vector<PlannedPass> passes;         // indexed by PassId: declaration order, culled included
  std::vector<PassId> order;               // kept passes, execution order
  std::vector<Batch> batches;              // submission order
  std::vector<FinalBarrier> finalBarriers;
  // Per logical queue: the last batch the host waits for (kInvalidIndex: none);
  // batches after it are the frame's tail.
  std::array<uint32_t, kQueueClassCount> hostWaitBatch{kInvalidIndex, kInvalidIndex, kInvalidIndex};
  std::vector<ExternalUse> externalUses;   // by resource, then queue
  std::vector<Heap> heaps;
  uint64_t heapBytes = 0;                  // total of heaps, as placed
  uint64_t heapBytesWithoutAliasing = 0;   // what the heaps would take if nothing aliased
  bool memoryEstimated = false;            // requirements were guessed, not queried from a device

  // Flat storage behind the Ranges above.
  std::vector<ResourceAccess> accesses;  // grouped by pass
  std::vector<Barrier> barriers;         // grouped by pass
  std::vector<SemaphoreWait> waits;      // grouped by batch
  std::vector<ResourceId> aliases;       // grouped by resource

  std::span<const ResourceAccess> accessesOf(PassId p) const { return slice(accesses, passes[p.index].accesses); }
  std::span<const Barrier> barriersBefore(PassId p) const { return slice(barriers, passes[p.index].barriersBefore); }
  std::span<const Barrier> barriersAfter(PassId p) const { return slice(barriers, passes[p.index].barriersAfter); }
  std::span<const PassId> passesOf(const Batch& batch) const { return slice(order, batch.passes); }
  std::span<const SemaphoreWait> waitsOf(const Batch& batch) const { return slice(waits, batch.waits); }
  std::span<const ResourceId> aliasesOf(ResourceId r) const { return slice(aliases, resources[r.index].aliasesWith); }
};

}  // namespace sg::graph
