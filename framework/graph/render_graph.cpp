#include <shadelgraph/graph/render_graph.hpp>

#include <utility>

namespace sg::graph {

// Room for a large frame from the start (a hundred passes, each writing a
// resource or two and reading a few): a new graph then seldom regrows its
// arrays (each regrowth a malloc, a copy and a free). Reserved memory nobody
// uses is never touched.
RenderGraph::RenderGraph() : declaration_(std::make_unique<GraphDeclaration>()) {
  constexpr std::size_t kPasses = 128, kResources = 192, kAccesses = 512;
  GraphDeclaration& d = *declaration_;
  d.resources.reserve(kResources);
  d.traits.reserve(kResources);
  d.versionCounts.reserve(kResources);
  d.passes.reserve(kPasses);
  d.passNames.reserve(kPasses);
  d.callbacks.reserve(kPasses);
  d.accesses.reserve(kAccesses);
}

// Inline in every create/import: a call to it goes through the PLT (an
// indirect jump per declared resource).
[[gnu::always_inline]] inline ResourceHandle RenderGraph::added() {
  const ResourceDecl& decl = declaration_->resources.back();
  declaration_->traits.push_back({decl.kind, decl.type, decl.readOnly, decl.image.format});
  declaration_->versionCounts.push_back(1);
  return {ResourceId{static_cast<uint32_t>(declaration_->resources.size() - 1)}, 0};
}

ResourceHandle RenderGraph::add(ResourceDecl&& decl) {
  declaration_->resources.push_back(std::move(decl));
  return added();
}

// Transients (most resources of a frame) are built in place, every field given
// (C++20 parenthesized aggregate initialization, in ResourceDecl's field
// order): a value-initialized emplace_back() zeroes the whole decl first (a
// `rep stos`) and then stores over it; an aggregate temporary costs a move.
ResourceHandle RenderGraph::createImage(std::string name, const ImageDesc& desc) {
  declaration_->resources.emplace_back(ResourceKind::TransientImage, ResourceType::Image, false, ResourceId{},
                                       ResourceId{}, desc, BufferDesc{}, ResourceState{}, ResourceState{},
                                       std::move(name));
  return added();
}

ResourceHandle RenderGraph::createBuffer(std::string name, const BufferDesc& desc) {
  declaration_->resources.emplace_back(ResourceKind::TransientBuffer, ResourceType::Buffer, false, ResourceId{},
                                       ResourceId{}, ImageDesc{}, desc, ResourceState{}, ResourceState{},
                                       std::move(name));
  return added();
}

namespace {
// An imported resource of either type: the same states and read-only flag.
ResourceDecl importDecl(std::string name, ResourceType type, ImportedState initial, FinalState final, ImportMode mode) {
  ResourceDecl decl{.kind = ResourceKind::Imported, .type = type};
  decl.name = std::move(name);
  decl.initialState = initial;
  decl.finalState = final;
  decl.readOnly = mode == ImportMode::ReadOnly;
  return decl;
}
}  // namespace

ResourceHandle RenderGraph::importImage(std::string name, const ImageDesc& desc, ImportedState initial,
                                        FinalState final, ImportMode mode) {
  ResourceDecl decl = importDecl(std::move(name), ResourceType::Image, initial, final, mode);
  decl.image = desc;
  return add(std::move(decl));
}

ResourceHandle RenderGraph::importBuffer(std::string name, const BufferDesc& desc, ImportedState initial,
                                         FinalState final, ImportMode mode) {
  ResourceDecl decl = importDecl(std::move(name), ResourceType::Buffer, initial, final, mode);
  decl.buffer = desc;
  return add(std::move(decl));
}

ResourceHandle RenderGraph::importPersistentImage(std::string name, const ImageDesc& desc, ResourceState resting) {
  ResourceDecl decl{.kind = ResourceKind::Persistent, .type = ResourceType::Image};
  decl.name = std::move(name);
  decl.image = desc;
  decl.initialState = resting;
  decl.finalState = resting;
  return add(std::move(decl));
}

ResourceHandle RenderGraph::importPersistentBuffer(std::string name, const BufferDesc& desc, ResourceState resting) {
  ResourceDecl decl{.kind = ResourceKind::Persistent, .type = ResourceType::Buffer};
  decl.name = std::move(name);
  decl.buffer = desc;
  decl.initialState = resting;
  decl.finalState = resting;
  return add(std::move(decl));
}

ResourceHandle RenderGraph::history(ResourceHandle persistent) {
  if (!isValid(persistent.id)) return {};
  std::vector<ResourceDecl>& resources = declaration_->resources;
  if (resources[persistent.id.index].history.valid()) return {resources[persistent.id.index].history, 0};
  const ResourceDecl& source = resources[persistent.id.index];
  ResourceDecl decl{.kind = ResourceKind::History, .type = source.type};
  decl.name = source.name + ".history";
  decl.image = source.image;
  decl.buffer = source.buffer;
  // Last frame's copy was left in the persistent resource's final state, and
  // becomes next frame's persistent resource: it must be left in its initial state.
  decl.initialState = source.finalState;
  decl.finalState = source.initialState;
  decl.readOnly = true;
  decl.historyOf = persistent.id;
  const ResourceHandle handle = add(std::move(decl));  // invalidates `source`
  resources[persistent.id.index].history = handle.id;
  return handle;
}

Pass& RenderGraph::addPass(std::string name, QueueClass queue) {
  return addPass(std::move(name), queue, defaultPassKind(queue));
}

Pass& RenderGraph::addPass(std::string name, QueueClass queue, PassKind kind) {
  const PassId id{passCount()};
  const auto end = static_cast<uint32_t>(declaration_->accesses.size());
  declaration_->passes.push_back({.accesses = {end, 0}, .queue = queue, .kind = kind});
  declaration_->passNames.push_back(std::move(name));
  declaration_->callbacks.emplace_back();
  // The builder of pass i is always Pass(declaration, i): the ones made before
  // a clear() serve again.
  const uint32_t block = id.index / kBuilderBlock;
  if (block == builders_.size()) builders_.emplace_back().reserve(kBuilderBlock);
  std::vector<Pass>& builders = builders_[block];
  if (id.index % kBuilderBlock == builders.size()) builders.emplace_back(*declaration_, id);  // within capacity
  return builders[id.index % kBuilderBlock];
}

void RenderGraph::markOutput(ResourceHandle version) { declaration_->outputs.push_back(version); }

void RenderGraph::clear() {
  declaration_->resources.clear();
  declaration_->traits.clear();
  declaration_->passes.clear();
  declaration_->passNames.clear();
  declaration_->callbacks.clear();
  declaration_->accesses.clear();
  declaration_->outputs.clear();
  declaration_->versionCounts.clear();
}

}  // namespace sg::graph
