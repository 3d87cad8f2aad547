#pragma once
// Runs a compiled render-graph plan: creates the transients and places them
// in heap memory exactly as the plan says (aliasing included), records each
// batch's passes between the plan's barriers, submits per queue batch with
// timeline semaphores, and times every pass on the GPU (timestamps) and CPU.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <shadelgraph/gpu/buffer.hpp>
#include <shadelgraph/gpu/descriptors.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/gpu/image.hpp>
#include <shadelgraph/gpu/timestamps.hpp>
#include <shadelgraph/graph/compile.hpp>
#include <shadelgraph/graph/compile_options.hpp>
#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/render_graph.hpp>

namespace sg::gpu {

struct PassTiming {
  std::string name;
  graph::QueueClass queue = graph::QueueClass::Graphics;
  double gpuMs = 0.0;
  double gpuStartMs = 0.0;  // since the frame's first timestamp
  double cpuMs = 0.0;       // recording the pass's commands
};

struct FrameTimings {
  std::vector<PassTiming> passes;  // execution order
  double frameMs = 0.0;            // CPU wall time: compile + record + submit + wait
  double gpuMs = 0.0;              // first to last timestamp
};

class GraphExecutor {
 public:
  explicit GraphExecutor(Device& device);
  ~GraphExecutor();
  GraphExecutor(const GraphExecutor&) = delete;
  GraphExecutor& operator=(const GraphExecutor&) = delete;

  // Physical resources behind imported, persistent and history declarations,
  // for the next execute().
  void bindImage(graph::ResourceHandle handle, const Image& image);
  void bindBuffer(graph::ResourceHandle handle, const Buffer& buffer);

  // Compiles with the transients' real memory requirements: the Vulkan objects
  // are created from a first compile's resolved descriptions and queried. The
  // plan stays valid until the next compile(), whose memory it reuses.
  const graph::CompiledPlan& compile(const graph::RenderGraph& graph, graph::CompileOptions options);
  // Records, submits and waits for one frame.
  FrameTimings execute(const graph::RenderGraph& graph, const graph::CompiledPlan& plan);

  // Serialize passes so each one's timestamps bracket its execution (default
  // on: exact per-pass times; off: passes may overlap, only the frame time is exact).
  void setExactPassTimes(bool exact) { exactPassTimes_ = exact; }

  // Command buffers allocated so far, all queues: as many as the largest
  // frame's batches, not growing with the number of frames.
  size_t commandBufferCount() const;

  // Bytes of device memory the transients of the last executed plan occupy.
  uint64_t transientBytes() const { return transientBytes_; }
  const Image& image(graph::ResourceId id) const;
  const Buffer& buffer(graph::ResourceId id) const;

 private:
  struct Transient {
    graph::ResourceDesc desc;
    std::string name;
    std::optional<Image> image;
    std::optional<Buffer> buffer;
  };
  Transient& transientFor(graph::ResourceId id, const graph::PlannedResource& planned);
  void placeTransients(const graph::CompiledPlan& plan);
  // The `index`-th command buffer of queue `q` this frame, begun for one submit.
  VkCommandBuffer beginCommandBuffer(uint32_t q, uint32_t index);
  void recordBarriers(VkCommandBuffer cmd, const graph::CompiledPlan& plan,
                      const std::vector<const graph::Barrier*>& barriers) const;

  Device& device_;
  // Reset at the start of each frame (the last one has been waited for). Its
  // command buffers are allocated once, as batches first need them, and
  // re-recorded every frame: a buffer allocated per frame would never return.
  VkCommandPool commandPools_[graph::kQueueClassCount] = {};  // one per logical queue's family
  std::vector<VkCommandBuffer> commandBuffers_[graph::kQueueClassCount];
  VkSemaphore timelines_[graph::kQueueClassCount] = {};
  uint64_t timelineBase_[graph::kQueueClassCount] = {};
  GpuTimer timer_;
  DescriptorArena descriptors_;
  std::map<uint32_t, const Image*> boundImages_;
  std::map<uint32_t, const Buffer*> boundBuffers_;
  // Transients by resource index; recreated when their description changes.
  std::map<uint32_t, Transient> transients_;
  // One for the draft (estimated memory), one for the plan: each keeps its memory from frame to frame.
  graph::PlanCompiler draftCompiler_;
  graph::PlanCompiler planCompiler_;
  std::vector<Allocation> heaps_;
  std::vector<graph::MemoryPlacement> placed_;  // placement the transients are bound at
  uint64_t transientBytes_ = 0;
  bool exactPassTimes_ = true;
};

}  // namespace sg::gpu
