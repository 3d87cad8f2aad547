#pragma once

#include <shadelgraph/graph/assign_queues.hpp>
#include <shadelgraph/graph/compile_options.hpp>
#include <shadelgraph/graph/compiled_plan.hpp>
#include <shadelgraph/graph/cross_queue_order.hpp>
#include <shadelgraph/graph/dependencies.hpp>
#include <shadelgraph/graph/place_transients.hpp>
#include <shadelgraph/graph/plan_inputs.hpp>
#include <shadelgraph/graph/plan_barriers.hpp>
#include <shadelgraph/graph/plan_resources.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/graph/version_table.hpp>

#include <vector>

namespace sg::graph {

// Runs the compile steps in turn: validate (throws GraphError with every
// error), cullPasses, orderPasses, planResources, placeTransients (memory
// requirements from `options`), planBarriers, assignQueues.
CompiledPlan compile(const RenderGraph& graph, const CompileOptions& options = {});

// The same, frame after frame: keeps the plan and every step's output between
// calls and reuses their memory, so a steady-state recompile allocates (almost)
// nothing. A graph that declares exactly what the last compile saw (callbacks
// aside) with the same options gets the last plan back without compiling: a
// frame loop whose frame did not change pays for declaring and comparing only.
// The plan returned stays valid until the next compile().
class PlanCompiler {
 public:
  // keepInputs false: never compare or keep the inputs (one-off compiles).
  explicit PlanCompiler(bool keepInputs = true) : keepInputs_(keepInputs) {}

  const CompiledPlan& compile(const RenderGraph& graph, const CompileOptions& options = {});
  const CompiledPlan& plan() const { return plan_; }
  CompiledPlan takePlan() {
    compiled_.forget();
    return std::move(plan_);
  }
  // Whether the last compile() returned the plan before it unchanged.
  bool reusedLastPlan() const { return reused_; }

 private:
  bool keepInputs_ = true;
  PlanInputs compiled_;  // what plan_ was compiled from
  bool reused_ = false;
  VersionTable versions_;
  DependencyGraph deps_;
  std::vector<bool> culled_;
  std::vector<bool> needed_;  // per pass: the frame's results need it
  std::vector<ResourceUsage> usage_;
  std::vector<MemoryRequirements> requirements_;
  std::vector<TransientLifetime> transients_;
  std::vector<uint32_t> positions_;  // per pass: its position in the order
  CrossQueueOrder queueOrder_;
  MemoryPlan memory_;
  BarrierPlan barriers_;
  QueueSchedule schedule_;
  CompiledPlan plan_;
};

}  // namespace sg::graph
