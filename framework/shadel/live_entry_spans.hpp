#pragma once
// Which owned remap entries the per-entry passes of a frame visit (shadel-clear,
// shadel-allocate, work-fill, shadel-gutter, support-expand, shade-frame, the
// shadel-mask clear): only those of live instances, not every allocated one.
// An instance is live when it is shaded this frame or still holds stored
// chunks. The owned entries are grouped by instance (buildGpuTables), so the
// live ones form runs; each run is one dispatch per pass.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <shadelgraph/shadel/shadel_gpu_tables.hpp>
#include <shadelgraph/shadel/shaders/decoupled_interface.h>

namespace sg::shadel {

using EntrySpan = shader::SgEntrySpan;  // owned entries [begin, end)

// Runs beyond this many are joined across their smallest gaps: a few entries
// visited in vain cost less than one more dispatch in every per-entry pass.
inline constexpr size_t kMaxLiveSpans = 8;
static_assert(kMaxLiveSpans <= shader::kMaxBlockSpans, "live-entry-blocks takes every span in its push constants");

// Per instance id, its run of owned entries in tables.ownedEntries ({0, 0}: none).
std::vector<EntrySpan> ownedEntryRuns(const ShadelGpuTables& tables);

// The runs of the entries of `live` instances (any order, repeats allowed),
// ascending, touching runs joined, at most maxSpans (> 0). Empty: no pass has
// an entry to visit.
std::vector<EntrySpan> liveEntrySpans(std::span<const EntrySpan> runs, std::span<const uint32_t> live,
                                      size_t maxSpans = kMaxLiveSpans);

// Owned entries the spans cover.
uint64_t entriesIn(std::span<const EntrySpan> spans);

// The live instances frame after frame: those shaded now and those shaded the
// frame before, which still hold stored chunks. One frame in the spans with
// nothing marked frees all of an instance's chunks (shadel-allocate's first
// step), so it is left out after that; left in longer, a returning instance
// would find chunks stored frames ago and keep their stale shading.
class LiveInstances {
 public:
  // This frame's live instances, given the ones it shades; remembers `shaded`.
  std::vector<uint32_t> next(std::span<const uint32_t> shaded);

 private:
  std::vector<uint32_t> shadedBefore_;
};

}  // namespace sg::shadel
