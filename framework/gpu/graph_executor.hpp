#pragma once
// Runs a compiled render-graph plan: creates the transients and places them
// in heap memory exactly as the plan says (aliasing included), records each
// batch's passes between the plan's barriers, submits per queue batch with
// timeline semaphores, and times every pass on the GPU (timestamps) and CPU.
// With more than one frame in flight, execute() returns once the frame's
// results are done and leaves its tail (work only later frames need, e.g. a
// shade frame on async compute) running; later frames wait for it through the
// timelines where they use the same persistent memory (frame_boundary.hpp).
#include <array>
#include <chrono>
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
  bool tail = false;        // in the frame's tail: runs past the frame (its GPU times come later)
  double gpuClockMs = 0.0;  // when it started on the GPU, on the executor's clock (see FrameTimings)
  double cpuClockMs = 0.0;  // when its recording started, on the executor's clock
};

struct FrameTimings {
  std::vector<PassTiming> passes;  // execution order
  double frameMs = 0.0;            // CPU wall time: compile + record + submit + wait
  double gpuMs = 0.0;              // first to last timestamp (of the passes timed: the tail's come later)
  uint64_t frame = 0;              // the executor's frame number, from 0
  // Clocks for traces over several frames: ms since the executor was created.
  // GPU times are on that clock too when the device calibrates its clock
  // with the host's (clocksAligned), else ms since the executor's first timestamp.
  bool clocksAligned = false;
  double submittedCpuClockMs = 0.0;  // its last batch was submitted
  double doneCpuClockMs = 0.0;       // the host had waited for it
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
  // Whether the last compile() handed back the plan before it (the frame declared the same graph).
  bool reusedLastPlan() const { return draftCompiler_.reusedLastPlan() && planCompiler_.reusedLastPlan(); }
  // Records, submits and waits for one frame.
  FrameTimings execute(const graph::RenderGraph& graph, const graph::CompiledPlan& plan);

  // Frames recorded while earlier ones run (1: every frame is waited for
  // whole, tail included). Waits for the frames in flight when it changes.
  void setFramesInFlight(uint32_t frames);
  uint32_t framesInFlight() const { return uint32_t(slots_.size()); }
  // Waits for every frame in flight (tails included).
  void finish();
  // Waits until the next frame's slot is free: the frame that used it last,
  // its tail included, has completed. Before writing what that frame read
  // (host-written per-frame buffers, one per frame in flight).
  void beginFrame();
  // The tails of frames that have completed since the last call, timed.
  std::vector<FrameTimings> takeCompletedTails();
  // The timeline waits the last frame's batches were submitted with (the
  // plan's and those on earlier frames), by batch: what tests check.
  struct SubmittedWait {
    graph::QueueClass queue = graph::QueueClass::Graphics;
    uint64_t value = 0;
    friend bool operator==(const SubmittedWait&, const SubmittedWait&) = default;
  };
  const std::vector<std::vector<SubmittedWait>>& lastFrameWaits() const { return lastWaits_; }

  // Serialize passes so each one's timestamps bracket its execution (default
  // on: exact per-pass times; off: passes may overlap, only the frame time is exact).
  void setExactPassTimes(bool exact) { exactPassTimes_ = exact; }

  // Command buffers allocated so far, all queues: as many as the largest
  // frame's batches, not growing with the number of frames.
  size_t commandBufferCount() const;

  // Bytes of device memory the transients of the last executed plan occupy.
  uint64_t transientBytes() const { return slots_[current_].transientBytes; }
  const Image& image(graph::ResourceId id) const;
  const Buffer& buffer(graph::ResourceId id) const;

 private:
  struct Transient {
    graph::ResourceDesc desc;
    std::string name;
    std::optional<Image> image;
    std::optional<Buffer> buffer;
  };
  // What one frame in flight records into and uses; reused only once that
  // frame (its tail included) has completed.
  struct Slot {
    VkCommandPool pools[graph::kQueueClassCount] = {};  // one per logical queue's family
    // Allocated once, as batches first need them, and re-recorded: a buffer
    // allocated per frame would never return.
    std::vector<VkCommandBuffer> buffers[graph::kQueueClassCount];
    std::unique_ptr<GpuTimer> timer;
    std::unique_ptr<DescriptorArena> descriptors;
    // Transients by resource index; recreated when their description changes.
    std::map<uint32_t, Transient> transients;
    std::vector<Allocation> heaps;
    std::vector<graph::MemoryPlacement> placed;  // placement the transients are bound at
    uint64_t transientBytes = 0;
    uint64_t signalled[graph::kQueueClassCount] = {};  // its frame's last timeline value per queue
    std::optional<FrameTimings> tail;  // its frame's tail passes, timed when it completes
    std::vector<uint32_t> tailScopes;  // their timer scopes
  };
  Transient makeTransient(const graph::PlannedResource& planned) const;
  Transient& transientFor(std::map<uint32_t, Transient>& transients, graph::ResourceId id,
                          const graph::PlannedResource& planned, std::vector<graph::MemoryPlacement>* placed);
  void placeTransients(Slot& slot, const graph::CompiledPlan& plan);
  Slot makeSlot();
  void destroySlot(Slot& slot);
  // Waits until the slot's last frame completed and keeps its tail's timings.
  void retire(Slot& slot);
  // The `index`-th command buffer of queue `q` of the slot, begun for one submit.
  VkCommandBuffer beginCommandBuffer(Slot& slot, uint32_t q, uint32_t index);
  void recordBarriers(VkCommandBuffer cmd, const graph::CompiledPlan& plan,
                      const std::vector<const graph::Barrier*>& barriers) const;
  // The physical resource behind an external resource of the plan (0: not bound).
  uint64_t physicalKey(graph::ResourceId id) const;
  double gpuClockMs(uint64_t ns);

  Device& device_;
  VkSemaphore timelines_[graph::kQueueClassCount] = {};
  uint64_t timelineBase_[graph::kQueueClassCount] = {};
  std::vector<Slot> slots_;
  uint32_t current_ = 0;
  uint64_t frames_ = 0;
  // Per physical external resource: the timeline value per queue of the last
  // batch that used it (0: none), what a later frame's first use on another queue waits for.
  std::map<uint64_t, std::array<uint64_t, graph::kQueueClassCount>> lastUse_;
  std::vector<FrameTimings> completedTails_;
  std::vector<std::vector<SubmittedWait>> lastWaits_;
  std::map<uint32_t, const Image*> boundImages_;
  std::map<uint32_t, const Buffer*> boundBuffers_;
  // Objects only asked for their memory requirements (never bound or used).
  std::map<uint32_t, Transient> probes_;
  // One for the draft (estimated memory), one for the plan: each keeps its memory from frame to frame.
  graph::PlanCompiler draftCompiler_;
  graph::PlanCompiler planCompiler_;
  bool exactPassTimes_ = true;
  std::chrono::steady_clock::time_point created_ = std::chrono::steady_clock::now();  // 0 ms on the clocks
  std::optional<int64_t> hostMinusDeviceNs_;  // calibration of the device's clock, when it has one
  uint64_t gpuOriginNs_ = 0;  // uncalibrated: the first timestamp read is 0 ms
  double clockMs() const;
};

}  // namespace sg::gpu
