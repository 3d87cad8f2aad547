#include <shadelgraph/graph/plan_inputs.hpp>

namespace sg::graph {

bool PlanInputs::matches(const GraphDeclaration& declared, const CompileOptions& options) const {
  // Cheapest tests first: a changed graph usually differs in a count or an access.
  return valid_ && !options.queryMemoryRequirements && options.outputWidth == outputWidth_ &&
         options.outputHeight == outputHeight_ && options.enableAliasing == enableAliasing_ &&
         options.externalWritesAreSideEffects == externalWritesAreSideEffects_ &&
         declared.passes.size() == passes_.size() && declared.resources.size() == resources_.size() &&
         declared.accesses == accesses_ && declared.passes == passes_ && declared.outputs == outputs_ &&
         options.memoryRequirements == memoryRequirements_ && declared.resources == resources_ &&
         declared.passNames == passNames_;
}

void PlanInputs::remember(const GraphDeclaration& declared, const CompileOptions& options) {
  valid_ = !options.queryMemoryRequirements;
  if (!valid_) return;
  resources_ = declared.resources;
  passes_ = declared.passes;
  passNames_ = declared.passNames;
  accesses_ = declared.accesses;
  outputs_ = declared.outputs;
  outputWidth_ = options.outputWidth;
  outputHeight_ = options.outputHeight;
  enableAliasing_ = options.enableAliasing;
  externalWritesAreSideEffects_ = options.externalWritesAreSideEffects;
  memoryRequirements_ = options.memoryRequirements;
}

}  // namespace sg::graph
