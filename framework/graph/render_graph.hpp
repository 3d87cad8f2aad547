#pragma once

#include <shadelgraph/graph/graph_declaration.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/graph/pass.hpp>
#include <shadelgraph/graph/resource_desc.hpp>
#include <shadelgraph/graph/sync_types.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace sg::graph {

enum class ImportMode : uint8_t { ReadWrite, ReadOnly };

// Builds the declaration of one frame: resources, passes and outputs.
// compile() turns it into a CompiledPlan. Movable, not copyable.
class RenderGraph {
 public:
  RenderGraph();

  ResourceHandle createImage(std::string name, const ImageDesc& desc);
  ResourceHandle createBuffer(std::string name, const BufferDesc& desc);
  ResourceHandle importImage(std::string name, const ImageDesc& desc, ImportedState initial, FinalState final,
                             ImportMode mode = ImportMode::ReadWrite);
  ResourceHandle importBuffer(std::string name, const BufferDesc& desc, ImportedState initial, FinalState final,
                              ImportMode mode = ImportMode::ReadWrite);
  // A plugin-owned resource whose contents survive frames. It is found in and
  // left in `resting`; its stages/access are the synchronization point between
  // frames (AllCommands is a safe choice).
  ResourceHandle importPersistentImage(std::string name, const ImageDesc& desc, ResourceState resting);
  ResourceHandle importPersistentBuffer(std::string name, const BufferDesc& desc, ResourceState resting);
  // Last frame's copy of a persistent resource (read-only; the owner swaps the
  // two physical resources between frames). Declared once per persistent resource.
  ResourceHandle history(ResourceHandle persistent);

  // The pass kind defaults from the queue (Graphics: Raster, AsyncCompute: Compute, Transfer: Transfer).
  Pass& addPass(std::string name, QueueClass queue);
  Pass& addPass(std::string name, QueueClass queue, PassKind kind);

  // The pass producing this version (and everything it needs) is never culled.
  void markOutput(ResourceHandle version);

  // Forgets every declaration but keeps the memory, for declaring the next
  // frame into the same graph. Invalidates the Pass references handed out.
  void clear();

  // The declaration as plain data.
  const GraphDeclaration& declaration() const { return *declaration_; }
  uint32_t passCount() const { return static_cast<uint32_t>(declaration_->passes.size()); }
  uint32_t resourceCount() const { return static_cast<uint32_t>(declaration_->resources.size()); }
  const PassDecl& pass(PassId id) const { return declaration_->passes[id.index]; }
  const std::string& passName(PassId id) const { return declaration_->passNames[id.index]; }
  // What the executor invokes to record the pass (empty if none was given).
  const ExecuteFn& callback(PassId id) const { return declaration_->callbacks[id.index]; }
  std::span<const ResourceAccess> accessesOf(PassId id) const { return declaration_->accessesOf(id); }
  const ResourceDecl& resource(ResourceId id) const { return declaration_->resources[id.index]; }
  bool isValid(ResourceId id) const { return id.index < declaration_->resources.size(); }
  std::span<const ResourceHandle> outputs() const { return declaration_->outputs; }

 private:
  ResourceHandle add(ResourceDecl&& decl);
  // Registers the resource last appended to the declaration (its traits and version count).
  ResourceHandle added();

  // On the heap so that Pass builders keep pointing at it when the graph moves.
  std::unique_ptr<GraphDeclaration> declaration_;
  // The Pass builders, by PassId, in blocks of kBuilderBlock whose storage
  // never moves (the Pass& handed out stay valid while passes are added).
  static constexpr uint32_t kBuilderBlock = 128;
  std::vector<std::vector<Pass>> builders_;
};

}  // namespace sg::graph
