#pragma once

#include <shadelgraph/graph/memory_requirements.hpp>
#include <shadelgraph/graph/resource_desc.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace sg::graph {

using MemoryRequirementsQuery = std::function<MemoryRequirements(const ResourceDesc&)>;

struct CompileOptions {
  // The extent relative image sizes are scaled from.
  uint32_t outputWidth = 0;
  uint32_t outputHeight = 0;
  // Transients with disjoint lifetimes on one queue share memory.
  bool enableAliasing = true;
  // Passes writing an imported or persistent resource are kept like side-effect passes.
  bool externalWritesAreSideEffects = true;
  // Memory requirements of transients, from the device. Either a vector indexed
  // by ResourceId (entries of other resources are ignored) or a query called
  // once per used transient with its resolved description. If neither is given
  // they are estimated (CompiledPlan::memoryEstimated) -- for tools and tests only.
  std::vector<MemoryRequirements> memoryRequirements;
  MemoryRequirementsQuery queryMemoryRequirements;
};

}  // namespace sg::graph
