#include <shadelgraph/shadel/live_entry_spans.hpp>

#include <algorithm>

namespace sg::shadel {

std::vector<EntrySpan> ownedEntryRuns(const ShadelGpuTables& tables) {
  std::vector<EntrySpan> runs(tables.instances.size(), EntrySpan{0, 0});
  // Entries are grouped by instance in ascending id: each run ends where the next allocated one starts.
  auto end = uint32_t(tables.ownedEntries.size());
  for (size_t id = tables.instances.size(); id-- > 0;) {
    const GpuShadelInstance& instance = tables.instances[id];
    if (instance.levelCount == 0) continue;
    runs[id] = {instance.firstOwnedEntry, end};
    end = instance.firstOwnedEntry;
  }
  return runs;
}

std::vector<EntrySpan> liveEntrySpans(std::span<const EntrySpan> runs, std::span<const uint32_t> live,
                                      size_t maxSpans) {
  std::vector<EntrySpan> spans;
  for (const uint32_t id : live)
    if (id < runs.size() && runs[id].begin < runs[id].end) spans.push_back(runs[id]);
  std::sort(spans.begin(), spans.end(), [](const EntrySpan& a, const EntrySpan& b) { return a.begin < b.begin; });
  std::vector<EntrySpan> joined;
  for (const EntrySpan& s : spans) {
    if (!joined.empty() && s.begin <= joined.back().end)
      joined.back().end = std::max(joined.back().end, s.end);
    else
      joined.push_back(s);
  }
  maxSpans = std::max<size_t>(maxSpans, 1);
  while (joined.size() > maxSpans) {
    size_t closest = 0;
    for (size_t i = 1; i + 1 < joined.size(); ++i)
      if (joined[i + 1].begin - joined[i].end < joined[closest + 1].begin - joined[closest].end) closest = i;
    joined[closest].end = joined[closest + 1].end;
    joined.erase(joined.begin() + std::ptrdiff_t(closest) + 1);
  }
  return joined;
}

uint64_t entriesIn(std::span<const EntrySpan> spans) {
  uint64_t n = 0;
  for (const EntrySpan& s : spans) n += s.end - s.begin;
  return n;
}

std::vector<uint32_t> LiveInstances::next(std::span<const uint32_t> shaded) {
  std::vector<uint32_t> live(shadedBefore_);
  live.insert(live.end(), shaded.begin(), shaded.end());
  std::sort(live.begin(), live.end());
  live.erase(std::unique(live.begin(), live.end()), live.end());
  shadedBefore_.assign(shaded.begin(), shaded.end());
  return live;
}

}  // namespace sg::shadel
