#include <shadelgraph/gpu/graph_executor.hpp>

#include <algorithm>

#include <shadelgraph/gpu/barriers.hpp>
#include <shadelgraph/gpu/error.hpp>
#include <shadelgraph/gpu/graph_to_vulkan.hpp>
#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/compile.hpp>

namespace sg::gpu {
namespace {

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

GraphExecutor::GraphExecutor(Device& device) : device_(device), timer_(device.context()), descriptors_(device.context()) {
  VkDevice vk = device.context().device();
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) {
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.queueFamilyIndex = device.context().queue(static_cast<Queue>(q)).family;
    SG_VK(vkCreateCommandPool(vk, &pool, nullptr, &commandPools_[q]));
    VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO};
    type.semaphoreType = VK_SEMAPHORE_TYPE_TIMELINE;
    VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    info.pNext = &type;
    SG_VK(vkCreateSemaphore(vk, &info, nullptr, &timelines_[q]));
  }
}

GraphExecutor::~GraphExecutor() {
  VkDevice vk = device_.context().device();
  vkDeviceWaitIdle(vk);
  transients_.clear();
  for (auto& heap : heaps_) device_.memory().free(heap);
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) {
    vkDestroyCommandPool(vk, commandPools_[q], nullptr);
    vkDestroySemaphore(vk, timelines_[q], nullptr);
  }
}

void GraphExecutor::bindImage(graph::ResourceHandle handle, const Image& image) { boundImages_[handle.id.index] = &image; }

void GraphExecutor::bindBuffer(graph::ResourceHandle handle, const Buffer& buffer) {
  boundBuffers_[handle.id.index] = &buffer;
}

GraphExecutor::Transient& GraphExecutor::transientFor(graph::ResourceId id, const graph::PlannedResource& planned) {
  auto it = transients_.find(id.index);
  if (it != transients_.end() && it->second.desc == planned.desc && it->second.name == planned.name) return it->second;
  Transient t{planned.desc, planned.name, {}, {}};
  if (planned.desc.type == graph::ResourceType::Image)
    t.image.emplace(device_.context(), imageDescOf(planned.desc, planned.name));
  else
    t.buffer.emplace(device_.context(), bufferDescOf(planned.desc, planned.name));
  placed_.clear();  // a new object is unbound: placement must run again
  return transients_.insert_or_assign(id.index, std::move(t)).first->second;
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
    Transient& t = transientFor(graph::ResourceId{i}, r);
    const VkMemoryRequirements req = t.image ? t.image->memoryRequirements() : t.buffer->memoryRequirements();
    options.memoryRequirements[i] = {req.size, req.alignment, req.memoryTypeBits};
  }
  options.queryMemoryRequirements = nullptr;
  return planCompiler_.compile(graph, options);
}

void GraphExecutor::placeTransients(const graph::CompiledPlan& plan) {
  std::vector<graph::MemoryPlacement> wanted(plan.resources.size());
  for (uint32_t i = 0; i < plan.resources.size(); ++i)
    if (graph::isTransient(plan.resources[i].kind) && !plan.resources[i].culled) wanted[i] = plan.resources[i].memory;
  bool same = wanted == placed_ && heaps_.size() == plan.heaps.size();
  for (size_t h = 0; same && h < plan.heaps.size(); ++h) same = heaps_[h].size >= plan.heaps[h].size;
  for (uint32_t i = 0; same && i < plan.resources.size(); ++i)
    if (wanted[i].placed()) {
      auto it = transients_.find(i);
      same = it != transients_.end() && it->second.desc == plan.resources[i].desc;
    }
  if (same) return;

  // Vulkan objects bind memory once: recreate them all, then the heaps.
  vkDeviceWaitIdle(device_.context().device());
  transients_.clear();
  for (auto& heap : heaps_) device_.memory().free(heap);
  heaps_.clear();
  transientBytes_ = 0;
  for (const auto& h : plan.heaps) {
    VkMemoryRequirements req{std::max<uint64_t>(h.size, 1), h.alignment, h.memoryTypeBits};
    heaps_.push_back(device_.memory().allocate(req, MemoryLocation::Device, "transient"));
    transientBytes_ += h.size;
  }
  for (uint32_t i = 0; i < plan.resources.size(); ++i) {
    if (!wanted[i].placed()) continue;
    Transient& t = transientFor(graph::ResourceId{i}, plan.resources[i]);
    const Allocation& heap = heaps_[wanted[i].heap];
    if (t.image)
      t.image->bindMemory(heap.memory, heap.offset + wanted[i].offset);
    else
      t.buffer->bindMemory(heap.memory, heap.offset + wanted[i].offset);
  }
  placed_ = std::move(wanted);
}

const Image& GraphExecutor::image(graph::ResourceId id) const {
  if (auto it = transients_.find(id.index); it != transients_.end() && it->second.image) return *it->second.image;
  if (auto it = boundImages_.find(id.index); it != boundImages_.end()) return *it->second;
  throw GpuError("render graph: no image is bound to resource #" + std::to_string(id.index));
}

const Buffer& GraphExecutor::buffer(graph::ResourceId id) const {
  if (auto it = transients_.find(id.index); it != transients_.end() && it->second.buffer) return *it->second.buffer;
  if (auto it = boundBuffers_.find(id.index); it != boundBuffers_.end()) return *it->second;
  throw GpuError("render graph: no buffer is bound to resource #" + std::to_string(id.index));
}

size_t GraphExecutor::commandBufferCount() const {
  size_t count = 0;
  for (const auto& buffers : commandBuffers_) count += buffers.size();
  return count;
}

VkCommandBuffer GraphExecutor::beginCommandBuffer(uint32_t q, uint32_t index) {
  auto& buffers = commandBuffers_[q];
  if (index >= buffers.size()) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = commandPools_[q];
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
  placeTransients(plan);
  for (auto pool : commandPools_) SG_VK(vkResetCommandPool(vk, pool, 0));
  descriptors_.reset();
  timer_.reset();

  FrameTimings timings;
  std::vector<uint32_t> scopes;  // timer scope per entry of timings.passes
  uint64_t lastSignal[graph::kQueueClassCount] = {};
  uint32_t usedBuffers[graph::kQueueClassCount] = {};
  for (uint32_t b = 0; b < plan.batches.size(); ++b) {
    const graph::Batch& batch = plan.batches[b];
    const uint32_t q = graph::queueIndex(batch.queue);
    VkCommandBuffer cmd = beginCommandBuffer(q, usedBuffers[q]++);
    for (graph::PassId id : plan.passesOf(batch)) {
      const graph::PlannedPass& planned = plan.passes[id.index];
      std::vector<const graph::Barrier*> before;
      for (const auto& barrier : plan.barriersBefore(id)) before.push_back(&barrier);
      // The pass's time includes its barriers: layout transitions are its cost.
      const uint32_t scope = timer_.begin(cmd, planned.name);
      recordBarriers(cmd, plan, before);
      CpuTimer recordTimer;
      if (const auto& callback = graph.callback(id)) {
        PassContext ctx(cmd, device_, descriptors_, *this);
        callback(ctx);
      }
      const double cpuMs = recordTimer.elapsedMs();
      if (exactPassTimes_) {
        // Drivers may still be executing the pass when its end timestamp is
        // written (lavapipe runs work asynchronously until a barrier): wait for it.
        memoryBarrier(cmd, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT}, {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT});
      }
      timer_.end(cmd, scope);
      std::vector<const graph::Barrier*> after;
      for (const auto& barrier : plan.barriersAfter(id)) after.push_back(&barrier);
      for (const auto& f : plan.finalBarriers)
        if (f.afterPass == id) after.push_back(&f.barrier);
      recordBarriers(cmd, plan, after);
      timings.passes.push_back({planned.name, planned.queue, 0.0, 0.0, cpuMs});
      scopes.push_back(scope);
    }
    SG_VK(vkEndCommandBuffer(cmd));

    std::vector<VkSemaphoreSubmitInfo> waits;
    for (const auto& w : plan.waitsOf(batch)) {
      VkSemaphoreSubmitInfo s{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
      s.semaphore = timelines_[graph::queueIndex(w.queue)];
      s.value = timelineBase_[graph::queueIndex(w.queue)] + w.value;
      s.stageMask = toVk(w.dstStages);
      if (!s.stageMask) s.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
      waits.push_back(s);
    }
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = timelines_[q];
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    // Every batch signals its queue's timeline: the plan's value when someone
    // waits on it, else the next private value, so the frame end can be awaited.
    lastSignal[q] = std::max(lastSignal[q] + 1, batch.signalValue);
    signal.value = timelineBase_[q] + lastSignal[q];
    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.waitSemaphoreInfoCount = uint32_t(waits.size());
    submit.pWaitSemaphoreInfos = waits.data();
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;
    SG_VK(vkQueueSubmit2(device_.context().queue(toQueue(batch.queue)).queue, 1, &submit, VK_NULL_HANDLE));
  }

  // Wait for every queue's last batch, then move the timelines' bases past this frame.
  std::vector<VkSemaphore> semaphores;
  std::vector<uint64_t> values;
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q)
    if (lastSignal[q]) {
      semaphores.push_back(timelines_[q]);
      values.push_back(timelineBase_[q] + lastSignal[q]);
    }
  VkSemaphoreWaitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO};
  wait.semaphoreCount = uint32_t(semaphores.size());
  wait.pSemaphores = semaphores.data();
  wait.pValues = values.data();
  if (!semaphores.empty()) SG_VK(vkWaitSemaphores(vk, &wait, UINT64_MAX));
  for (uint32_t q = 0; q < graph::kQueueClassCount; ++q) timelineBase_[q] += lastSignal[q];

  const auto gpu = timer_.read();
  double gpuEnd = 0.0;
  for (size_t i = 0; i < timings.passes.size(); ++i) {
    timings.passes[i].gpuMs = gpu[scopes[i]].gpuMs;
    timings.passes[i].gpuStartMs = gpu[scopes[i]].startMs;
    gpuEnd = std::max(gpuEnd, gpu[scopes[i]].startMs + gpu[scopes[i]].gpuMs);
  }
  timings.gpuMs = gpuEnd;
  timings.frameMs = frameTimer.elapsedMs();
  return timings;
}

}  // namespace sg::gpu
