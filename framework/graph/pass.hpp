#pragma once

#include <shadelgraph/graph/graph_declaration.hpp>
#include <shadelgraph/graph/handles.hpp>

#include <span>
#include <string>

namespace sg::graph {

// Declares one pass: what plugin code holds between RenderGraph::addPass() and
// the end of the frame's declaration. References stay valid while more passes
// are added (and when the RenderGraph is moved).
class Pass {
 public:
  Pass(GraphDeclaration& declaration, PassId id) : declaration_(&declaration), id_(id) {}

  // Reads one version of a resource. `stages` overrides the pass kind's default
  // shader stage for Sampled / Storage* / Uniform accesses.
  void read(ResourceHandle resource, Access access, ShaderStage stages = ShaderStage::None);
  // Writes over `resource` and returns the version this pass produces. Writing
  // the same handle twice in one pass returns the same new version.
  [[nodiscard]] ResourceHandle write(ResourceHandle resource, Access access, ShaderStage stages = ShaderStage::None);
  // Keeps the pass (and what it reads) even if nobody reads its results.
  Pass& sideEffect();
  Pass& execute(ExecuteFn callback);

  PassId id() const { return id_; }
  const std::string& name() const { return declaration_->passNames[id_.index]; }
  QueueClass queue() const { return decl().queue; }
  PassKind kind() const { return decl().kind; }
  bool hasSideEffect() const { return decl().sideEffect; }
  // Valid until the next access is declared on any pass.
  std::span<const ResourceAccess> accesses() const { return declaration_->accessesOf(id_); }

 private:
  const PassDecl& decl() const { return declaration_->passes[id_.index]; }

  GraphDeclaration* declaration_;
  PassId id_;
};

}  // namespace sg::graph
