#pragma once

#include <shadelgraph/graph/compile_options.hpp>
#include <shadelgraph/graph/graph_declaration.hpp>

#include <string>
#include <vector>

namespace sg::graph {

// What a compile read: the declaration without its callbacks (the plan never
// refers to them) and the options that shape a plan. PlanCompiler keeps the
// last successful compile's inputs; a frame that declares exactly the same
// graph gets the same plan back without compiling it again. Compared in full,
// not by hash: a collision would hand a frame the wrong barriers.
class PlanInputs {
 public:
  // True when `declared` and `options` are what remember() saw last. A memory
  // query function cannot be compared, so options with one never match.
  bool matches(const GraphDeclaration& declared, const CompileOptions& options) const;
  // Keeps a copy (into this object's memory, so steady-state misses allocate nothing).
  void remember(const GraphDeclaration& declared, const CompileOptions& options);
  void forget() { valid_ = false; }

 private:
  bool valid_ = false;
  // The declaration's own fields; traits and versionCounts follow from these.
  std::vector<ResourceDecl> resources_;
  std::vector<PassDecl> passes_;
  std::vector<std::string> passNames_;
  std::vector<ResourceAccess> accesses_;
  std::vector<ResourceHandle> outputs_;
  // CompileOptions without the query.
  uint32_t outputWidth_ = 0;
  uint32_t outputHeight_ = 0;
  bool enableAliasing_ = true;
  bool externalWritesAreSideEffects_ = true;
  std::vector<MemoryRequirements> memoryRequirements_;
};

}  // namespace sg::graph
