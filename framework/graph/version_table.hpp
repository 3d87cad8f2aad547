#pragma once

#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/graph/render_graph.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace sg::graph {

// A ResourceKind as a bit of VersionTable::PassKinds.
constexpr uint8_t kindBit(ResourceKind kind) { return static_cast<uint8_t>(1u << static_cast<uint8_t>(kind)); }
constexpr uint8_t kExternalKinds =
    kindBit(ResourceKind::Imported) | kindBit(ResourceKind::Persistent) | kindBit(ResourceKind::History);

// Who produces and who reads each version of each resource, over all declared
// passes (culled or not). Every compile step starts from this index.
struct VersionTable {
  // A pass writing over a version somebody else already wrote over (branching).
  struct BranchingWrite {
    uint32_t slot = kInvalidIndex;  // the version written over
    PassId pass;
  };

  // Versions of resource r live in slots [firstSlot[r], firstSlot[r + 1]).
  std::vector<uint32_t> firstSlot;
  // Per slot: the pass producing that version; invalid for version 0 and for
  // versions no pass writes.
  std::vector<PassId> producer;
  // Readers of slot s are readers[firstReader[s] .. firstReader[s + 1]). A pass
  // reading a version twice is listed twice; a pass that also writes over the
  // version (read-modify-write) is listed too.
  std::vector<uint32_t> firstReader;
  std::vector<PassId> readers;
  std::vector<BranchingWrite> branches;
  // Per pass: the kinds of resource it accesses and writes (kindBit() bits),
  // gathered in the same walk, so that the steps looking for passes that use
  // imported or persistent resources skip the others without walking their accesses.
  struct PassKinds {
    uint8_t accessed = 0;
    uint8_t written = 0;
  };
  std::vector<PassKinds> passKinds;
  // Every pass's accesses, in pass order, and the index of the pass each
  // belongs to (then a few entries of slack), so that forEachAccess() walks
  // all accesses in one loop instead of a short loop per pass, whose exit the
  // CPU mispredicts about once a pass (passes have a few accesses each, in
  // random numbers). The accesses are the declaration's own when it holds
  // them in pass order with nothing between (the usual case); else this
  // copy, which is empty otherwise.
  std::vector<ResourceAccess> accessesInPassOrder;
  bool copiedAccesses = false;
  std::vector<uint32_t> passOfAccess;
  // indexVersions()'s working memory (the reads in declaration order, then unused
  // entries: one per access, so that listing a read needs no capacity test), kept for the next call.
  struct Read {
    uint32_t slot;
    PassId pass;
  };
  std::vector<Read> scratch;
  std::vector<uint32_t> kindsScratch;  // indexVersions()'s too: passKinds as it gathers them

  uint32_t versionCount(ResourceId r) const { return firstSlot[r.index + 1] - firstSlot[r.index]; }
  // kInvalidIndex if the version was never referenced.
  uint32_t slot(ResourceId r, uint32_t version) const {
    return version < versionCount(r) ? firstSlot[r.index] + version : kInvalidIndex;
  }
  PassId producerOf(ResourceId r, uint32_t version) const {
    const uint32_t s = slot(r, version);
    return s == kInvalidIndex ? PassId{} : producer[s];
  }
  // The pass writing over version `version` (the producer of version + 1).
  PassId overwriterOf(ResourceId r, uint32_t version) const { return producerOf(r, version + 1); }
  std::span<const PassId> readersOf(uint32_t slot) const {
    return {readers.data() + firstReader[slot], readers.data() + firstReader[slot + 1]};
  }
};

// Calls visit(pass index, access) for every access of every pass, in pass order
// (and, within a pass, in declaration order), in one loop.
template <class Visit>
void forEachAccess(const RenderGraph& graph, const VersionTable& versions, Visit&& visit) {
  const std::vector<ResourceAccess>& all =
      versions.copiedAccesses ? versions.accessesInPassOrder : graph.declaration().accesses;
  // (Locals, not the vectors: `visit` may store through pointers the compiler
  // cannot tell from the vectors' own, and would reload their bounds after each.)
  const ResourceAccess* access = all.data();
  const ResourceAccess* const end = access + all.size();
  for (const uint32_t* passOf = versions.passOfAccess.data(); access != end; ++access, ++passOf) visit(*passOf, *access);
}

// The same from the last access of the last pass to the first of the first.
template <class Visit>
void forEachAccessInReverse(const RenderGraph& graph, const VersionTable& versions, Visit&& visit) {
  const std::vector<ResourceAccess>& all =
      versions.copiedAccesses ? versions.accessesInPassOrder : graph.declaration().accesses;
  const ResourceAccess* const first = all.data();
  const uint32_t* passOf = versions.passOfAccess.data() + all.size();
  for (const ResourceAccess* access = first + all.size(); access != first;) visit(*--passOf, *--access);
}

VersionTable indexVersions(const RenderGraph& graph);
// The same into `table`, reusing its memory.
void indexVersions(const RenderGraph& graph, VersionTable& table);

}  // namespace sg::graph
