#include <shadelgraph/graph/version_table.hpp>

#include <algorithm>

namespace sg::graph {
namespace {

// Fills table.passOfAccess (and, if the declaration holds the passes'
// accesses out of order or with gaps, table.accessesInPassOrder).
void listPassOfAccess(const GraphDeclaration& declared, VersionTable& table) {
  // Eight entries at a time, past the pass's end (the next pass overwrites
  // them; the last one's land in the slack): one round for passes of up to
  // eight accesses, so the loop's exit is predictable. The positions count
  // the passes' accesses one after the other: the declaration's own if it
  // holds them so, which this loop finds out too, else a copy made below.
  constexpr uint32_t kWidth = 8;
  table.passOfAccess.resize(declared.accesses.size() + kWidth);  // at least as many as passes' accesses
  uint32_t* passOf = table.passOfAccess.data();
  bool inPassOrder = true;
  uint32_t next = 0;
  for (uint32_t p = 0; p < declared.passes.size(); ++p) {
    const Range accesses = declared.passes[p].accesses;
    inPassOrder &= accesses.first == next;
    for (uint32_t i = 0; i < accesses.count; i += kWidth) std::fill_n(passOf + next + i, kWidth, p);
    next += accesses.count;
  }
  inPassOrder &= next == declared.accesses.size();
  table.copiedAccesses = !inPassOrder;
  table.accessesInPassOrder.clear();
  if (!inPassOrder) [[unlikely]] {
    for (uint32_t p = 0; p < declared.passes.size(); ++p) {
      const std::span<const ResourceAccess> accesses = declared.accessesOf(PassId{p});
      table.accessesInPassOrder.insert(table.accessesInPassOrder.end(), accesses.begin(), accesses.end());
    }
  }
}

// Every write over a version that another pass already wrote over (the first
// writer, in declaration order, is the version's producer), in declaration order.
[[gnu::noinline]] void listBranches(const RenderGraph& graph, VersionTable& table) {
  const std::vector<uint32_t>& versionCounts = graph.declaration().versionCounts;
  for (uint32_t p = 0; p < graph.passCount(); ++p) {
    for (const ResourceAccess& a : graph.accessesOf(PassId{p})) {
      if (!graph.isValid(a.resource) || !a.write || a.version + 2 > versionCounts[a.resource.index]) continue;
      const uint32_t slot = table.firstSlot[a.resource.index] + a.version;
      if (table.producer[slot + 1].index != p) table.branches.push_back({slot, PassId{p}});
    }
  }
}

}  // namespace

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

  // Producers and reader counts, in one walk that also lists the reads for
  // placing them below. Reads and writes come in random order, so each access
  // takes both paths without a branch: a read is listed (the list's next entry
  // is written either way, and only a read advances it) and counted (+1 or
  // +0), and a write claims the version's producer if it has none (a read
  // stores its own slot's producer back unchanged). A second writer of a
  // version (branching, an error) is only noticed here; listBranches() names them.
  listPassOfAccess(graph.declaration(), table);
  table.producer.assign(slots, PassId{});
  table.firstReader.assign(slots + 1, 0);
  std::vector<VersionTable::Read>& reads = table.scratch;  // the first readCount entries are the reads
  const std::size_t accessCount = graph.declaration().accesses.size();
  if (reads.size() < accessCount) reads.resize(accessCount);  // at most one per access
  table.passKinds.resize(passCount);
  // Per pass, the kinds of resource accessed (low byte) and written (next
  // byte), as 32-bit words: byte stores would alias every pointer below.
  std::vector<uint32_t>& kindsScratch = table.kindsScratch;
  kindsScratch.assign(passCount, 0);
  uint32_t* kinds = kindsScratch.data();
  // Raw pointers in locals, kept in registers through the walk.
  const uint32_t* firstSlot = table.firstSlot.data();
  const ResourceTraits* resourceTraits = traits.data();
  uint32_t* readerCount = table.firstReader.data() + 1;
  PassId* producers = table.producer.data();
  VersionTable::Read* readList = reads.data();
  uint32_t readCount = 0;
  bool branching = false;
  forEachAccess(graph, table, [&](uint32_t p, const ResourceAccess& a) __attribute__((always_inline)) {
    const uint32_t r = a.resource.index;
    if (r >= resourceCount) [[unlikely]] return;  // !graph.isValid(a.resource)
    const uint32_t write = a.write ? 1u : 0u;
    const uint32_t kind = kindBit(resourceTraits[r].kind);
    kinds[p] |= kind << (8 * write);
    if (a.version + write >= firstSlot[r + 1] - firstSlot[r]) [[unlikely]] return;  // forged (validate() reports it)
    const uint32_t slot = firstSlot[r] + a.version;
    readList[readCount] = {slot, PassId{p}};
    readCount += 1 - write;
    readerCount[slot] += 1 - write;
    // Passes come in declaration order, so the first writer is the smallest
    // pass: min(producer, p) for a write, min(producer, invalid) for a read.
    uint32_t& producer = producers[slot + write].index;
    branching |= write & (producer < p);  // written over by an earlier pass
    producer = std::min(producer, p | (write - 1));
  });
  for (uint32_t p = 0; p < passCount; ++p) {
    const auto written = static_cast<uint8_t>(kinds[p] >> 8);
    table.passKinds[p] = {static_cast<uint8_t>(kinds[p] | written), written};
  }
  if (branching) [[unlikely]] listBranches(graph, table);
  for (uint32_t s = 0; s < slots; ++s) table.firstReader[s + 1] += table.firstReader[s];

  // Readers (counting sort: firstReader[s] serves as the cursor, then is restored).
  table.readers.resize(readCount);
  for (uint32_t i = 0; i < readCount; ++i) table.readers[table.firstReader[reads[i].slot]++] = reads[i].pass;
  std::copy_backward(table.firstReader.begin(), table.firstReader.end() - 1, table.firstReader.end());  // one memmove
  table.firstReader[0] = 0;
}

}  // namespace sg::graph
