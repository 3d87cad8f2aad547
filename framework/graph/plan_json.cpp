#include <shadelgraph/graph/plan_dump.hpp>

#include <nlohmann/json.hpp>

namespace sg::graph {
namespace {

using nlohmann::json;

json optionalIndex(uint32_t index) { return index == kInvalidIndex ? json(nullptr) : json(index); }

json barrierJson(const CompiledPlan& plan, const Barrier& b) {
  return {
      {"resource", plan.resources[b.resource.index].name},
      {"srcStages", toString(b.srcStages)},
      {"dstStages", toString(b.dstStages)},
      {"srcAccess", toString(b.srcAccess)},
      {"dstAccess", toString(b.dstAccess)},
      {"oldLayout", toString(b.oldLayout)},
      {"newLayout", toString(b.newLayout)},
      {"discard", b.discard},
  };
}

json barriersJson(const CompiledPlan& plan, std::span<const Barrier> barriers) {
  json list = json::array();
  for (const Barrier& b : barriers) list.push_back(barrierJson(plan, b));
  return list;
}

json waitsJson(std::span<const SemaphoreWait> waits) {
  json list = json::array();
  for (const SemaphoreWait& w : waits) {
    list.push_back({{"queue", toString(w.queue)}, {"value", w.value}, {"dstStages", toString(w.dstStages)}});
  }
  return list;
}

json stateJson(const ResourceState& state) {
  return {{"layout", toString(state.layout)}, {"stages", toString(state.stages)}, {"access", toString(state.access)}};
}

json passJson(const CompiledPlan& plan, PassId id) {
  const PlannedPass& pass = plan.passes[id.index];
  json accesses = json::array();
  for (const ResourceAccess& a : plan.accessesOf(id)) {
    accesses.push_back({
        {"resource", plan.resources[a.resource.index].name},
        {"access", toString(a.access)},
        {"mode", a.write ? "write" : "read"},
        {"version", a.version},
        {"stages", toString(a.stages)},
        {"accessFlags", toString(a.accessFlags)},
        {"layout", toString(a.layout)},
    });
  }
  // Semaphore waits happen before the first pass of a batch.
  const bool startsBatch = pass.batch != kInvalidIndex && plan.batches[pass.batch].passes.first == pass.orderIndex;
  return {
      {"name", pass.name},
      {"queue", toString(pass.queue)},
      {"kind", toString(pass.kind)},
      {"culled", pass.culled},
      {"sideEffect", pass.sideEffect},
      {"batch", optionalIndex(pass.batch)},
      {"orderIndex", optionalIndex(pass.orderIndex)},
      {"accesses", accesses},
      {"barriers", barriersJson(plan, plan.barriersBefore(id))},
      {"barriersAfter", barriersJson(plan, plan.barriersAfter(id))},
      {"waits", startsBatch ? waitsJson(plan.waitsOf(plan.batches[pass.batch])) : json::array()},
  };
}

json resourceJson(const CompiledPlan& plan, ResourceId id) {
  const PlannedResource& r = plan.resources[id.index];
  json out = {
      {"name", r.name},
      {"kind", toString(r.kind)},
      {"type", toString(r.desc.type)},
      {"culled", r.culled},
      {"queues", toString(r.desc.queues)},
      {"concurrent", r.desc.concurrent},
      {"firstUse", optionalIndex(r.firstUse)},
      {"lastUse", optionalIndex(r.lastUse)},
  };
  if (r.desc.type == ResourceType::Image) {
    const ResolvedImageDesc& d = r.desc.image;
    out["format"] = toString(d.format);
    out["width"] = d.width;
    out["height"] = d.height;
    out["depth"] = d.depth;
    out["layers"] = d.layers;
    out["mipLevels"] = d.mipLevels;
    out["samples"] = d.samples;
    out["usage"] = toString(r.desc.imageUsage);
  } else {
    out["size"] = r.desc.bufferSize;
    out["usage"] = toString(r.desc.bufferUsage);
  }
  if (isTransient(r.kind)) {
    out["memory"] = r.memory.placed()
                        ? json{{"heap", r.memory.heap}, {"offset", r.memory.offset}, {"size", r.memory.size}}
                        : json(nullptr);
    json aliases = json::array();
    for (const ResourceId other : plan.aliasesOf(id)) aliases.push_back(plan.resources[other.index].name);
    out["aliasesWith"] = aliases;
  } else {
    out["initialState"] = stateJson(r.initialState);
    out["finalState"] = stateJson(r.finalState);
    out["readOnly"] = r.readOnly;
    if (r.historyOf.valid()) out["historyOf"] = plan.resources[r.historyOf.index].name;
  }
  return out;
}

}  // namespace

std::string toJson(const CompiledPlan& plan) {
  json passes = json::array();
  for (uint32_t p = 0; p < plan.passes.size(); ++p) passes.push_back(passJson(plan, PassId{p}));
  json resources = json::array();
  for (uint32_t r = 0; r < plan.resources.size(); ++r) resources.push_back(resourceJson(plan, ResourceId{r}));
  json order = json::array();
  for (const PassId p : plan.order) order.push_back(plan.passes[p.index].name);
  json batches = json::array();
  for (const Batch& batch : plan.batches) {
    json names = json::array();
    for (const PassId p : plan.passesOf(batch)) names.push_back(plan.passes[p.index].name);
    batches.push_back({{"queue", toString(batch.queue)},
                       {"passes", names},
                       {"waits", waitsJson(plan.waitsOf(batch))},
                       {"signalValue", batch.signalValue},
                       {"tail", batch.tail}});
  }
  json finals = json::array();
  for (const FinalBarrier& f : plan.finalBarriers) {
    json entry = barrierJson(plan, f.barrier);
    entry["afterPass"] = f.afterPass.valid() ? json(plan.passes[f.afterPass.index].name) : json(nullptr);
    entry["batch"] = optionalIndex(f.batch);
    finals.push_back(entry);
  }
  json heaps = json::array();
  for (const Heap& h : plan.heaps) {
    heaps.push_back({{"size", h.size},
                     {"alignment", h.alignment},
                     {"memoryTypeBits", h.memoryTypeBits},
                     {"queues", toString(h.queues)},
                     {"aliasing", h.aliasing}});
  }
  const json document = {
      {"output", {{"width", plan.outputWidth}, {"height", plan.outputHeight}}},
      {"passes", passes},
      {"resources", resources},
      {"order", order},
      {"batches", batches},
      {"finalBarriers", finals},
      {"heaps", heaps},
      {"memory",
       {{"heapBytes", plan.heapBytes},
        {"heapBytesWithoutAliasing", plan.heapBytesWithoutAliasing},
        {"estimated", plan.memoryEstimated}}},
  };
  return document.dump(2);
}

}  // namespace sg::graph
