#include <shadelgraph/graph/version_table.hpp>

#include <algorithm>

namespace sg::graph {

VersionTable indexVersions(const RenderGraph& graph) {
  VersionTable table;
  indexVersions(graph, table);
  return table;
}

void indexVersions(const RenderGraph& graph, VersionTable& table) {
  const uint32_t resourceCount = graph.resourceCount();
  const uint32_t passCount = graph.passCount();
  // Slots: one per version the declaration references (counted while declaring).
  // Versions of forged handles are left out; validate() reports them.
  const std::vector<uint32_t>& versionCounts = graph.declaration().versionCounts;
  const std::vector<ResourceTraits>& traits = graph.declaration().traits;
  table.firstSlot.resize(resourceCount + 1);
  table.firstSlot[0] = 0;
  for (uint32_t r = 0; r < resourceCount; ++r) table.firstSlot[r + 1] = table.firstSlot[r] + versionCounts[r];
  const uint32_t slots = table.firstSlot[resourceCount];

  // Producers (a second writer of the same version is branching) and reader
  // counts, in one walk that also lists the reads for placing them below.
  table.producer.assign(slots, PassId{});
  table.firstReader.assign(slots + 1, 0);
  table.branches.clear();
  std::vector<VersionTable::Read>& reads = table.scratch;
  reads.clear();
  reads.reserve(graph.declaration().accesses.size());  // at most one per access: grown once, not by doubling
  table.passKinds.assign(passCount, {});
  for (uint32_t p = 0; p < passCount; ++p) {
    VersionTable::PassKinds& kinds = table.passKinds[p];
    for (const ResourceAccess& a : graph.accessesOf(PassId{p})) {
      if (!graph.isValid(a.resource)) continue;
      const uint8_t kind = kindBit(traits[a.resource.index].kind);
      kinds.accessed |= kind;
      if (a.write) kinds.written |= kind;
      if (a.version + (a.write ? 2u : 1u) > versionCounts[a.resource.index]) continue;
      const uint32_t slot = table.firstSlot[a.resource.index] + a.version;
      if (!a.write) {
        ++table.firstReader[slot + 1];
        reads.push_back({slot, PassId{p}});
        continue;
      }
      PassId& producer = table.producer[slot + 1];
      if (!producer.valid()) {
        producer = PassId{p};
      } else if (producer.index != p) {
        table.branches.push_back({slot, PassId{p}});
      }
    }
  }
  for (uint32_t s = 0; s < slots; ++s) table.firstReader[s + 1] += table.firstReader[s];

  // Readers (counting sort: firstReader[s] serves as the cursor, then is restored).
  table.readers.resize(reads.size());
  for (const VersionTable::Read& r : reads) table.readers[table.firstReader[r.slot]++] = r.pass;
  std::copy_backward(table.firstReader.begin(), table.firstReader.end() - 1, table.firstReader.end());  // one memmove
  table.firstReader[0] = 0;
}

}  // namespace sg::graph
