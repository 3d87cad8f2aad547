#include <shadelgraph/graph/compile.hpp>

#include <shadelgraph/graph/cull.hpp>
#include <shadelgraph/graph/frame_boundary.hpp>
#include <shadelgraph/graph/order.hpp>
#include <shadelgraph/graph/plan_resources.hpp>
#include <shadelgraph/graph/validate.hpp>

#include <stdexcept>
#include <utility>

namespace sg::graph {
namespace {

// The plan entry of every resource and, in the same sweep, the requirements of
// the used transients (from the options, or estimated) and their lifetimes
// for placement. `requirements` is indexed by ResourceId.
void planAllResources(const RenderGraph& graph, const std::vector<PassId>& order, const CompileOptions& options,
                      std::vector<ResourceUsage>& usage, std::vector<PlannedResource>& resources,
                      std::vector<MemoryRequirements>& requirements, std::vector<TransientLifetime>& transients,
                      bool& estimated) {
  gatherUsage(graph, order, usage);
  resources.resize(graph.resourceCount());
  requirements.assign(graph.resourceCount(), MemoryRequirements{});
  transients.clear();
  transients.reserve(graph.resourceCount());
  estimated = false;
  for (uint32_t r = 0; r < graph.resourceCount(); ++r) {
    PlannedResource& resource = resources[r];
    planResource(graph.resource(ResourceId{r}), usage[r], options.outputWidth, options.outputHeight, resource);
    if (!isTransient(resource.kind) || resource.culled) continue;
    if (!options.memoryRequirements.empty()) {
      if (r >= options.memoryRequirements.size()) {
        throw std::invalid_argument("CompileOptions::memoryRequirements has no entry for '" + resource.name + "'");
      }
      requirements[r] = options.memoryRequirements[r];
    } else if (options.queryMemoryRequirements) {
      requirements[r] = options.queryMemoryRequirements(resource.desc);
    } else {
      requirements[r] = estimateMemoryRequirements(resource.desc);
      estimated = true;
    }
    resource.requirements = requirements[r];
    transients.push_back({r, resource.firstUse, resource.lastUse, resource.desc.queues});
  }
}

// Runs `step` with `storage` lent to `output`: the step writes straight into
// the plan's memory (no copy, and the same buffer every frame).
template <class T, class Step>
void lendTo(std::vector<T>& storage, std::vector<T>& output, Step&& step) {
  output.swap(storage);
  step();
  output.swap(storage);
}

}  // namespace

CompiledPlan compile(const RenderGraph& graph, const CompileOptions& options) {
  PlanCompiler compiler(/*keepInputs=*/false);
  compiler.compile(graph, options);
  return compiler.takePlan();
}

const CompiledPlan& PlanCompiler::compile(const RenderGraph& graph, const CompileOptions& options) {
  reused_ = compiled_.matches(graph.declaration(), options);
  if (reused_) return plan_;
  compiled_.forget();  // until this compile succeeds (validate may throw)

  indexVersions(graph, versions_);
  // One dependency graph over all passes: validate() looks for cycles in it,
  // and the later steps ignore the edges of culled passes.
  buildDependencies(graph, versions_, {}, deps_);
  if (std::vector<ValidationError> errors = validate(graph, versions_, deps_, options); !errors.empty()) {
    throw GraphError(std::move(errors));
  }
  cullPasses(graph, versions_, options.externalWritesAreSideEffects, culled_);

  CompiledPlan& plan = plan_;
  plan.outputWidth = options.outputWidth;
  plan.outputHeight = options.outputHeight;
  orderPasses(deps_, culled_, plan.order);
  // What the results need, once: orderTailLast() keeps the order topological,
  // so planFrameBoundary() would find the same.
  std::vector<bool>& needed = needed_;
  neededByResults(graph, versions_, deps_, plan.order, needed);
  orderTailLast(needed, plan.order);
  planAllResources(graph, plan.order, options, usage_, plan.resources, requirements_, transients_,
                   plan.memoryEstimated);
  lendTo(plan.aliases, memory_.aliases, [&] {
    lendTo(plan.heaps, memory_.heaps, [&] {
      // Aliasing across queues relies on the semaphore waits the dependencies make.
      if (options.enableAliasing) orderAcrossQueues(graph, plan.order, deps_, queueOrder_);
      placeTransients(transients_, static_cast<uint32_t>(plan.resources.size()), requirements_,
                      options.enableAliasing, memory_, options.enableAliasing ? &queueOrder_ : nullptr);
    });
  });
  for (uint32_t r = 0; r < plan.resources.size(); ++r) {
    PlannedResource& resource = plan.resources[r];
    resource.memory = memory_.placements[r];
    resource.aliasesWith = memory_.aliasesWith[r];
  }
  plan.heapBytes = memory_.heapBytes;
  plan.heapBytesWithoutAliasing = memory_.heapBytesWithoutAliasing;

  lendTo(plan.barriers, barriers_.barriers, [&] {
    lendTo(plan.finalBarriers, barriers_.finals,
           [&] { planBarriers(graph, plan.order, plan.resources, plan.aliases, memory_.takeOverWaits, barriers_); });
  });
  lendTo(plan.batches, schedule_.batches, [&] {
    lendTo(plan.waits, schedule_.waits,
           [&] { assignQueues(graph, plan.order, deps_, barriers_.handoffs, schedule_); });
  });
  planFrameBoundary(graph, versions_, needed, schedule_.passBatch, plan);

  // Accesses: one copy when the declaration holds them in pass order already
  // (passes declared one after the other; indexVersions() found out), else pass by pass.
  const GraphDeclaration& declared = graph.declaration();
  const bool inPassOrder = !versions_.copiedAccesses;
  plan.accesses.clear();
  if (inPassOrder) plan.accesses.assign(declared.accesses.begin(), declared.accesses.end());

  positions_.assign(graph.passCount(), kInvalidIndex);
  for (uint32_t position = 0; position < plan.order.size(); ++position) positions_[plan.order[position].index] = position;
  plan.passes.resize(graph.passCount());
  for (uint32_t p = 0; p < graph.passCount(); ++p) {
    const PassDecl& pass = graph.pass(PassId{p});
    PlannedPass& out = plan.passes[p];
    // A frame loop declares the same names frame after frame: comparing is
    // cheaper than copying (a copy-assignment calls memcpy and rewrites the length).
    if (const std::string& name = declared.passNames[p]; out.name != name) out.name = name;
    out.queue = pass.queue;
    out.kind = pass.kind;
    out.sideEffect = pass.sideEffect;
    out.culled = culled_[p];
    if (inPassOrder) {
      out.accesses = pass.accesses;
    } else {
      const std::span<const ResourceAccess> accesses = graph.accessesOf(PassId{p});
      out.accesses = {static_cast<uint32_t>(plan.accesses.size()), static_cast<uint32_t>(accesses.size())};
      plan.accesses.insert(plan.accesses.end(), accesses.begin(), accesses.end());
    }
    out.barriersBefore = barriers_.before[p];
    out.barriersAfter = barriers_.after[p];
    out.batch = schedule_.passBatch[p];
    out.orderIndex = positions_[p];
  }
  for (FinalBarrier& f : plan.finalBarriers) {
    if (f.afterPass.valid()) f.batch = schedule_.passBatch[f.afterPass.index];
  }
  if (keepInputs_) compiled_.remember(declared, options);
  return plan;
}

}  // namespace sg::graph
