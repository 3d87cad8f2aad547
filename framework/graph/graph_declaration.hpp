#pragma once

#include <shadelgraph/graph/access.hpp>
#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/graph/queue.hpp>
#include <shadelgraph/graph/range.hpp>
#include <shadelgraph/graph/resource_desc.hpp>
#include <shadelgraph/graph/sync_types.hpp>

#include <functional>
#include <string>
#include <vector>

namespace sg {
class PassContext;  // defined by framework/gpu: what an execute callback records through
}

namespace sg::graph {

using ExecuteFn = std::function<void(sg::PassContext&)>;

// One declared access of a pass to a resource version, with its synchronization
// scope already worked out (the compile steps never re-derive it).
struct ResourceAccess {
  ResourceId resource;
  // read: the version read; write: the version written over (the pass produces version + 1)
  uint32_t version = 0;
  Access access = Access::Sampled;
  bool write = false;  // declared through write() (validation checks it matches isWrite(access))
  ShaderStage shaderStages = ShaderStage::None;  // default applied; None for non-shader accesses
  Layout layout = Layout::Undefined;             // meaningless for buffers
  PipelineStage stages = PipelineStage::None;
  AccessFlag accessFlags = AccessFlag::None;
  friend bool operator==(const ResourceAccess&, const ResourceAccess&) = default;
};
static_assert(sizeof(ResourceAccess) == 16, "the compile steps stream these; keep them small");

// A declared resource. External kinds (Imported, Persistent, History) carry the
// state they are in at frame start and the state they must be left in.
struct ResourceDecl {
  ResourceKind kind = ResourceKind::TransientImage;
  ResourceType type = ResourceType::Image;
  bool readOnly = false;  // read-only imports and history resources
  ResourceId historyOf;   // History: the persistent resource it is last frame's copy of
  ResourceId history;     // Persistent: its history resource, once declared
  ImageDesc image;        // type == Image
  BufferDesc buffer;      // type == Buffer
  ResourceState initialState;
  ResourceState finalState;
  std::string name;
  friend bool operator==(const ResourceDecl&, const ResourceDecl&) = default;
};

// What the compile steps look up about a resource on every access: a copy of
// a few ResourceDecl fields in a compact array (the decls are large), so that
// those scattered lookups stay in cache. RenderGraph keeps it in step.
struct ResourceTraits {
  ResourceKind kind = ResourceKind::TransientImage;
  ResourceType type = ResourceType::Image;
  bool readOnly = false;
  Format format = Format::Undefined;  // type == Image
};

// What the compile steps read of every pass (its name and callback are kept
// apart, in GraphDeclaration, so that walking passes stays cache-friendly).
struct PassDecl {
  Range accesses;  // into GraphDeclaration::accesses
  QueueClass queue = QueueClass::Graphics;
  PassKind kind = PassKind::Raster;
  bool sideEffect = false;
  friend bool operator==(const PassDecl&, const PassDecl&) = default;
};

// A frame's declaration as plain data: what RenderGraph builds and the compile
// steps read. Each pass's accesses are contiguous in `accesses`, so the steps
// walk one array; a pass whose declaration is interleaved with another's gets
// its accesses moved to the end (the old copies stay behind, unreferenced).
struct GraphDeclaration {
  std::vector<ResourceDecl> resources;  // by ResourceId
  std::vector<ResourceTraits> traits;   // by ResourceId (see ResourceTraits)
  std::vector<PassDecl> passes;         // by PassId
  std::vector<std::string> passNames;   // by PassId
  std::vector<ExecuteFn> callbacks;     // by PassId
  std::vector<ResourceAccess> accesses;
  std::vector<ResourceHandle> outputs;
  // Per resource: how many versions accesses name (1 + the highest), kept up
  // to date while declaring so that indexing versions needs no extra walk.
  std::vector<uint32_t> versionCounts;

  std::span<const ResourceAccess> accessesOf(PassId p) const { return slice(accesses, passes[p.index].accesses); }
};

}  // namespace sg::graph
