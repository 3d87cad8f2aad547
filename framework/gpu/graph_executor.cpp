#include <shadelgraph/gpu/graph_executor.hpp>

#include <algorithm>
#include <utility>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/gpu/graph_to_vulkan.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/compile.hpp>

namespace sg::gpu {
namespace {

constexpr size_t kKeptTails = 64;

// One batch's vkQueueSubmit2, kept when it is submitted later.
struct Submission {
  VkQueue queue = VK_NULL_HANDLE;
  std::vector<VkSemaphoreSubmitInfo> waits;
  VkSemaphoreSubmitInfo signal{};
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  void submit() const {
    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd;
    VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    info.waitSemaphoreInfoCount = uint32_t(waits.size());
    info.pWaitSemaphoreInfos = waits.data();
    info.commandBufferInfoCount = 1;
    info.pCommandBufferInfos = &cmdInfo;
    info.signalSemaphoreInfoCount = 1;
    info.pSignalSemaphoreInfos = &signal;
    SG_VK(vkQueueSubmit2(queue, 1, &info, VK_NULL_HANDLE));
  }
};

Queue toQueue(graph::QueueClass q) { return static_cast<Queue>(graph::queueIndex(q)); }

ImageDesc imageDescOf(const graph::ResourceDesc& d, const std::string& name) {
  return {.width = d.image.width, .height = d.image.height, .format = toVk(d.image.format),
          .usage = toVk(d.imageUsage), .mipLevels = d.image.mipLevels, .concurrent = d.concurrent,
          .name = name, .category = "transient"};
}

BufferDesc bufferDescOf(const graph::ResourceDesc& d, const std::string& name) {
  return {.size = d.bufferSize, .usage = toVk(d.bufferUsage), .name = name, .category = "transient",
          .concurrent = d.concurrent};
}

}  // namespace

GraphExecutor::GraphExecutor(Device& device)
    : device_(device), hostMinusDeviceNs_(device.context().hostMinusDeviceClockNs()) {
  VkDevice vk = device.context().device();
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) {
    VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    info.pNext = &type;
    SG_VK(vkCreateSemaphore(vk, &info, nullptr, &timelines_[q]));
  }
  slots_.push_back(makeSlot());
}

GraphExecutor::~GraphExecutor() {
  VkDevice vk = device_.context().device();
  vkDeviceWaitIdle(vk);
  for (auto& slot : slots_) destroySlot(slot);
  probes_.clear();
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) vkDestroySemaphore(vk, timelines_[q], nullptr);
}

GraphExecutor::Slot GraphExecutor::makeSlot() {
  Slot slot;
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.queueFamilyIndex = device_.context().queue(static_cast<Queue>(q)).family;
    SG_VK(vkCreateCommandPool(device_.context().device(), &pool, nullptr, &slot.pools[q]));
  }
  slot.timer = std::make_unique<GpuTimer>(device_.context());
  slot.descriptors = std::make_unique<DescriptorArena>(device_.context());
  return slot;
}

void GraphExecutor::destroySlot(Slot& slot) {
  slot.transients.clear();
  for (auto& heap : slot.heaps) device_.memory().free(heap);
  slot.heaps.clear();
  for (auto& pool : slot.pools) vkDestroyCommandPool(device_.context().device(), pool, nullptr);
  slot.timer.reset();
  slot.descriptors.reset();
}

void GraphExecutor::retire(Slot& slot) {
  std::vector<VkSemaphore> semaphores;
  std::vector<uint64_t> values;
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q)
    if (slot.signalled[q]) {
      semaphores.push_back(timelines_[q]);
      values.push_back(slot.signalled[q]);
    }
  VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  wait.semaphoreCount = uint32_t(semaphores.size());
  wait.pSemaphores = semaphores.data();
  wait.pValues = values.data();
  if (!semaphores.empty()) SG_VK(vkWaitSemaphores(device_.context().device(), &wait, UINT64_MAX));
  std::fill(std::begin(slot.signalled), std::end(slot.signalled), 0);
  if (slot.tail) {
    const auto gpu = slot.timer->read(slot.tailScopes);
    for (size_t i = 0; i < slot.tail->passes.size(); ++i) {
      const TimedScope& t = gpu[slot.tailScopes[i]];
      slot.tail->passes[i].gpuMs = t.gpuMs;
      slot.tail->passes[i].gpuClockMs = gpuClockMs(t.startNs);
    }
    completedTails_.push_back(std::move(*slot.tail));
    // Kept for a caller that asks (a trace); a long run nobody asks keeps the last few.
    if (completedTails_.size() > kKeptTails) completedTails_.erase(completedTails_.begin());
    slot.tail.reset();
  }
}

void GraphExecutor::setFramesInFlight(uint32_t frames) {
  frames = std::max(frames, 1u);
  if (frames == slots_.size()) return;
  finish();
  while (slots_.size() > frames) {
    destroySlot(slots_.back());
    slots_.pop_back();
  }
  while (slots_.size() < frames) slots_.push_back(makeSlot());
  current_ = std::min<uint32_t>(current_, uint32_t(slots_.size()) - 1);
}

void GraphExecutor::beginFrame() { retire(slots_[frames_ % slots_.size()]); }

void GraphExecutor::finish() {
  for (auto& slot : slots_) retire(slot);
}

std::vector<FrameTimings> GraphExecutor::takeCompletedTails() { return std::exchange(completedTails_, {}); }

double GraphExecutor::clockMs() const {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - created_).count();
}

double GraphExecutor::gpuClockMs(uint64_t ns) {
  if (hostMinusDeviceNs_) {
    const auto created = std::chrono::duration_cast<std::chrono::nanoseconds>(created_.time_since_epoch()).count();
    return (double(int64_t(ns) + *hostMinusDeviceNs_) - double(created)) * 1e-6;
  }
  if (!gpuOriginNs_) gpuOriginNs_ = ns;
  return (double(ns) - double(gpuOriginNs_)) * 1e-6;
}

void GraphExecutor::bindImage(graph::ResourceHandle handle, const Image& image) { boundImages_[handle.id.index] = &image; }

void GraphExecutor::bindBuffer(graph::ResourceHandle handle, const Buffer& buffer) {
  boundBuffers_[handle.id.index] = &buffer;
}

GraphExecutor::Transient GraphExecutor::makeTransient(const graph::PlannedResource& planned) const {
  Transient t{planned.desc, planned.name, {}, {}};
  if (planned.desc.type == graph::ResourceType::Image)
    t.image.emplace(device_.context(), imageDescOf(planned.desc, planned.name));
  else
    t.buffer.emplace(device_.context(), bufferDescOf(planned.desc, planned.name));
  return t;
}

GraphExecutor::Transient& GraphExecutor::transientFor(std::map<uint32_t, Transient>& transients, graph::ResourceId id,
                                                      const graph::PlannedResource& planned,
                                                      std::vector<graph::MemoryPlacement>* placed) {
  auto it = transients.find(id.index);
  if (it != transients.end() && it->second.desc == planned.desc && it->second.name == planned.name) return it->second;
  if (placed) placed->clear();  // a new object is unbound: placement must run again
  return transients.insert_or_assign(id.index, makeTransient(planned)).first->second;
}

const graph::CompiledPlan& GraphExecutor::compile(const graph::RenderGraph& graph, graph::CompileOptions options) {
  // First pass: resolved descriptions and usages (memory estimated).
  graph::CompileOptions first = options;
  first.memoryRequirements.clear();
  first.queryMemoryRequirements = nullptr;
  first.enableAliasing = false;
  const graph::CompiledPlan& draft = draftCompiler_.compile(graph, first);
  options.memoryRequirements.assign(draft.resources.size(), {});
  for (uint32_t i = 0; i < draft.resources.size(); ++i) {
    const auto& r = draft.resources[i];
    if (!graph::isTransient(r.kind) || r.culled) continue;
    // Probes, not the frames' objects: those may still be in use by a frame in flight.
    Transient& t = transientFor(probes_, graph::ResourceId{i}, r, nullptr);
    const VkMemoryRequirements req = t.image ? t.image->memoryRequirements() : t.buffer->memoryRequirements();
    options.memoryRequirements[i] = {req.size, req.alignment, req.memoryTypeBits};
  }
  options.queryMemoryRequirements = nullptr;
  return planCompiler_.compile(graph, options);
}

void GraphExecutor::placeTransients(Slot& slot, const graph::CompiledPlan& plan) {
  std::vector<graph::MemoryPlacement> wanted(plan.resources.size());
  for (uint32_t i = 0; i < plan.resources.size(); ++i)
    if (graph::isTransient(plan.resources[i].kind) && !plan.resources[i].culled) wanted[i] = plan.resources[i].memory;
  bool same = wanted == slot.placed && slot.heaps.size() == plan.heaps.size();
  for (size_t h = 0; same && h < plan.heaps.size(); ++h) same = slot.heaps[h].size >= plan.heaps[h].size;
  for (uint32_t i = 0; same && i < plan.resources.size(); ++i)
    if (wanted[i].placed()) {
      auto it = slot.transients.find(i);
      same = it != slot.transients.end() && it->second.desc == plan.resources[i].desc &&
             it->second.name == plan.resources[i].name;
    }
  if (same) return;

  // Vulkan objects bind memory once: recreate them all, then the heaps. The
  // slot's last frame has completed (retire), so nothing uses them.
  slot.transients.clear();
  for (auto& heap : slot.heaps) device_.memory().free(heap);
  slot.heaps.clear();
  slot.transientBytes = 0;
  for (const auto& h : plan.heaps) {
    VkMemoryRequirements req{std::max<uint64_t>(h.size, 1), h.alignment, h.memoryTypeBits};
    slot.heaps.push_back(device_.memory().allocate(req, MemoryLocation::Device, "transient"));
    slot.transientBytes += h.size;
  }
  for (uint32_t i = 0; i < plan.resources.size(); ++i) {
    if (!wanted[i].placed()) continue;
    Transient& t = transientFor(slot.transients, graph::ResourceId{i}, plan.resources[i], nullptr);
    const Allocation& heap = slot.heaps[wanted[i].heap];
    if (t.image)
      t.image->bindMemory(heap.memory, heap.offset + wanted[i].offset);
    else
      t.buffer->bindMemory(heap.memory, heap.offset + wanted[i].offset);
  }
  slot.placed = std::move(wanted);
}

const Image& GraphExecutor::image(graph::ResourceId id) const {
  const auto& transients = slots_[current_].transients;
  if (auto it = transients.find(id.index); it != transients.end() && it->second.image) return *it->second.image;
  if (auto it = boundImages_.find(id.index); it != boundImages_.end()) return *it->second;
  throw GpuError("render graph: no image is bound to resource #" + std::to_string(id.index));
}

const Buffer& GraphExecutor::buffer(graph::ResourceId id) const {
  const auto& transients = slots_[current_].transients;
  if (auto it = transients.find(id.index); it != transients.end() && it->second.buffer) return *it->second.buffer;
  if (auto it = boundBuffers_.find(id.index); it != boundBuffers_.end()) return *it->second;
  throw GpuError("render graph: no buffer is bound to resource #" + std::to_string(id.index));
}

size_t GraphExecutor::commandBufferCount() const {
  size_t count = 0;
  for (const auto& slot : slots_)
    for (const auto& buffers : slot.buffers) count += buffers.size();
  return count;
}

uint64_t GraphExecutor::physicalKey(graph::ResourceId id) const {
  if (auto it = boundImages_.find(id.index); it != boundImages_.end()) return uint64_t(it->second->handle());
  if (auto it = boundBuffers_.find(id.index); it != boundBuffers_.end()) return uint64_t(it->second->handle());
  return 0;
}

VkCommandBuffer GraphExecutor::beginCommandBuffer(Slot& slot, uint32_t q, uint32_t index) {
  auto& buffers = slot.buffers[q];
  if (index >= buffers.size()) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = slot.pools[q];
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    SG_VK(vkAllocateCommandBuffers(device_.context().device(), &alloc, &cmd));
    buffers.push_back(cmd);
  }
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  SG_VK(vkBeginCommandBuffer(buffers[index], &begin));
  return buffers[index];
}

void GraphExecutor::recordBarriers(VkCommandBuffer cmd, const graph::CompiledPlan& plan,
                                   const std::vector<const graph::Barrier*>& barriers) const {
  if (barriers.empty()) return;
  std::vector<VkImageMemoryBarrier2> images;
  std::vector<VkBufferMemoryBarrier2> buffers;
  for (const graph::Barrier* b : barriers) {
    const auto& r = plan.resources[b->resource.index];
    if (r.desc.type == graph::ResourceType::Image) {
      const Image& img = image(b->resource);
      VkImageMemoryBarrier2 v{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
      v.srcStageMask = toVk(b->srcStages);
      v.srcAccessMask = toVk(b->srcAccess);
      v.dstStageMask = toVk(b->dstStages);
      v.dstAccessMask = toVk(b->dstAccess);
      v.oldLayout = b->discard ? VK_IMAGE_LAYOUT_UNDEFINED : toVk(b->oldLayout);
      v.newLayout = toVk(b->newLayout);
      v.srcQueueFamilyIndex = v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      v.image = img.handle();
      v.subresourceRange = {aspectOf(img.desc().format), 0, VK_REMAINING_MIP_LEVELS, 0, VK_REMAINING_ARRAY_LAYERS};
      images.push_back(v);
    } else {
      VkBufferMemoryBarrier2 v{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
      v.srcStageMask = toVk(b->srcStages);
      v.srcAccessMask = toVk(b->srcAccess);
      v.dstStageMask = toVk(b->dstStages);
      v.dstAccessMask = toVk(b->dstAccess);
      v.srcQueueFamilyIndex = v.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
      v.buffer = buffer(b->resource).handle();
      v.size = VK_WHOLE_SIZE;
      buffers.push_back(v);
    }
  }
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = uint32_t(images.size());
  dep.pImageMemoryBarriers = images.data();
  dep.bufferMemoryBarrierCount = uint32_t(buffers.size());
  dep.pBufferMemoryBarriers = buffers.data();
  vkCmdPipelineBarrier2(cmd, &dep);
}

FrameTimings GraphExecutor::execute(const graph::RenderGraph& graph, const graph::CompiledPlan& plan) {
  CpuTimer frameTimer;
  VkDevice vk = device_.context().device();
  // The slot of the frame before last (or the last frame's, with one in flight) is free once it completed.
  current_ = uint32_t(frames_ % slots_.size());
  Slot& slot = slots_[current_];
  retire(slot);
  placeTransients(slot, plan);
  for (auto pool : slot.pools) SG_VK(vkResetCommandPool(vk, pool, 0));
  slot.descriptors->reset();
  slot.timer->reset();
  const bool inFlight = slots_.size() > 1;

  FrameTimings timings;
  timings.frame = frames_++;
  timings.clocksAligned = hostMinusDeviceNs_.has_value();
  std::vector<uint32_t> scopes;  // timer scope per entry of timings.passes
  uint64_t lastSignal[graph::kQueueClassCount] = {};
  uint32_t usedBuffers[graph::kQueueClassCount] = {};
  uint64_t hostWait[graph::kQueueClassCount] = {};  // absolute values the host waits for
  lastWaits_.assign(plan.batches.size(), {});
  // On one physical queue the tail runs after everything submitted before it
  // anyway; submitted only once the frame's results are done and timed, it
  // leaves the queue's work the host waits for (lavapipe makes a timestamp
  // available only when all submitted work is: reading the frame's times
  // would otherwise wait for its tail).
  const auto& context = device_.context();
  bool tailIsSuffix = true, seenTail = false;
  for (const auto& batch : plan.batches) {
    seenTail = seenTail || batch.tail;
    tailIsSuffix = tailIsSuffix && (!seenTail || batch.tail);
  }
  const bool deferTail = inFlight && tailIsSuffix &&
                         context.queue(Queue::AsyncCompute).queue == context.queue(Queue::Graphics).queue &&
                         context.queue(Queue::Transfer).queue == context.queue(Queue::Graphics).queue;
  std::vector<Submission> deferred;
  for (uint32_t b = 0; b < plan.batches.size(); ++b) {
    const graph::Batch& batch = plan.batches[b];
    const uint32_t q = graph::queueIndex(batch.queue);
    VkCommandBuffer cmd = beginCommandBuffer(slot, q, usedBuffers[q]++);
    for (graph::PassId id : plan.passesOf(batch)) {
      const graph::PlannedPass& planned = plan.passes[id.index];
      std::vector<const graph::Barrier*> before;
      for (const auto& barrier : plan.barriersBefore(id)) before.push_back(&barrier);
      // The pass's time includes its barriers: layout transitions are its cost.
      const uint32_t scope = slot.timer->begin(cmd, planned.name);
      recordBarriers(cmd, plan, before);
      const double cpuClock = clockMs();
      CpuTimer recordTimer;
      if (const auto& callback = graph.callback(id)) {
        PassContext ctx(cmd, device_, *slot.descriptors, *this);
        callback(ctx);
      }
      const double cpuMs = recordTimer.elapsedMs();
      if (exactPassTimes_) {
        // Drivers may still be executing the pass when its end timestamp is
        // written (lavapipe runs work asynchronously until a barrier): wait for it.
        memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT}, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT});
      }
      slot.timer->end(cmd, scope);
      std::vector<const graph::Barrier*> after;
      for (const auto& barrier : plan.barriersAfter(id)) after.push_back(&barrier);
      for (const auto& f : plan.finalBarriers)
        if (f.afterPass == id) after.push_back(&f.barrier);
      recordBarriers(cmd, plan, after);
      PassTiming pass{planned.name, planned.queue, 0.0, 0.0, cpuMs};
      pass.tail = inFlight && batch.tail;
      pass.cpuClockMs = cpuClock;
      timings.passes.push_back(pass);
      scopes.push_back(scope);
    }
    SG_VK(vkEndCommandBuffer(cmd));

    // The plan's waits, and those on earlier frames: an external resource's
    // first use on this queue waits for its last use on every other queue.
    uint64_t waitValue[graph::kQueueClassCount] = {};
    VkPipelineStageFlags2 waitStages[graph::kQueueClassCount] = {};
    const auto need = [&](uint32_t queue, uint64_t value, graph::PipelineStage stages) {
      waitValue[queue] = std::max(waitValue[queue], value);
      waitStages[queue] |= any(stages) ? toVk(stages) : VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    };
    for (const auto& w : plan.waitsOf(batch)) need(graph::queueIndex(w.queue), timelineBase_[graph::queueIndex(w.queue)] + w.value, w.dstStages);
    for (const auto& use : plan.externalUses) {
      if (use.firstBatch != b) continue;
      const auto it = lastUse_.find(physicalKey(use.resource));
      if (it == lastUse_.end()) continue;
      for (uint32_t other = 0; other < graph::kQueueClassCount; ++other)
        if (other != q && it->second[other]) need(other, it->second[other], use.firstStages);
    }
    std::vector<VkSemaphoreSubmitInfo> waits;
    for (uint32_t other = 0; other < graph::kQueueClassCount; ++other) {
      if (!waitValue[other]) continue;
      VkSemaphoreSubmitInfo s{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
      s.semaphore = timelines_[other];
      s.value = waitValue[other];
      s.stageMask = waitStages[other];
      waits.push_back(s);
      lastWaits_[b].push_back({static_cast<graph::QueueClass>(other), waitValue[other]});
    }
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = timelines_[q];
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    // Every batch signals its queue's timeline: the plan's value when someone
    // waits on it, else the next private value, so the frame end can be awaited.
    lastSignal[q] = std::max(lastSignal[q] + 1, batch.signalValue);
    signal.value = timelineBase_[q] + lastSignal[q];
    if (!inFlight || !batch.tail) hostWait[q] = signal.value;
    Submission submission{device_.context().queue(toQueue(batch.queue)).queue, std::move(waits), signal, cmd};
    if (deferTail && batch.tail)
      deferred.push_back(std::move(submission));
    else
      submission.submit();
  }
  timings.submittedCpuClockMs = clockMs();

  // Where this frame leaves each external resource, for the frames after it.
  for (const auto& use : plan.externalUses) {
    const uint64_t key = physicalKey(use.resource);
    if (!key) continue;
    auto& last = lastUse_[key];
    const uint32_t q = graph::queueIndex(use.queue);
    uint64_t value = 0;  // the batch's value: its index among the queue's batches, from 1
    for (uint32_t b = 0; b <= use.lastBatch; ++b) value += plan.batches[b].queue == use.queue ? 1 : 0;
    last[q] = timelineBase_[q] + value;
  }
  // Wait for what the host needs (everything, with one frame in flight),
  // then move the timelines' bases past this frame.
  std::vector<VkSemaphore> semaphores;
  std::vector<uint64_t> values;
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) {
    if (lastSignal[q]) slot.signalled[q] = timelineBase_[q] + lastSignal[q];
    if (hostWait[q]) {
      semaphores.push_back(timelines_[q]);
      values.push_back(hostWait[q]);
    }
  }
  VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  wait.semaphoreCount = uint32_t(semaphores.size());
  wait.pSemaphores = semaphores.data();
  wait.pValues = values.data();
  if (!semaphores.empty()) SG_VK(vkWaitSemaphores(vk, &wait, UINT64_MAX));
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) timelineBase_[q] += lastSignal[q];
  timings.doneCpuClockMs = clockMs();

  // The passes done now are timed now; the tail's when its slot is retired.
  std::vector<uint32_t> done, tail;
  FrameTimings tailTimings;
  tailTimings.frame = timings.frame;
  tailTimings.clocksAligned = timings.clocksAligned;
  for (size_t i = 0; i < timings.passes.size(); ++i) {
    if (timings.passes[i].tail) {
      tail.push_back(scopes[i]);
      tailTimings.passes.push_back(timings.passes[i]);
    } else {
      done.push_back(scopes[i]);
    }
  }
  if (!tail.empty()) {
    slot.tail = std::move(tailTimings);
    slot.tailScopes = std::move(tail);
  }
  const auto gpu = slot.timer->read(done);
  double gpuEnd = 0.0;
  for (size_t i = 0; i < timings.passes.size(); ++i) {
    if (timings.passes[i].tail) continue;
    const TimedScope& t = gpu[scopes[i]];
    timings.passes[i].gpuMs = t.gpuMs;
    timings.passes[i].gpuStartMs = t.startMs;
    timings.passes[i].gpuClockMs = gpuClockMs(t.startNs);
    gpuEnd = std::max(gpuEnd, t.startMs + t.gpuMs);
  }
  timings.gpuMs = gpuEnd;
  for (auto& submission : deferred) submission.submit();
  timings.frameMs = frameTimer.elapsedMs();
  return timings;
}

}  // namespace sg::gpu
