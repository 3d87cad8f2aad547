// Which owned remap entries the per-entry passes visit: the runs of the
// objects shaded this frame or still holding stored chunks.
#include <vector>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/live_entry_spans.hpp>

namespace sg::shader {
// Found by argument lookup: EntrySpan is shader::SgEntrySpan.
bool operator==(const SgEntrySpan& a, const SgEntrySpan& b) { return a.begin == b.begin && a.end == b.end; }
}  // namespace sg::shader

namespace sg::shadel {
namespace {

std::vector<EntrySpan> spans(std::initializer_list<std::pair<uint32_t, uint32_t>> list) {
  std::vector<EntrySpan> out;
  for (const auto& [b, e] : list) out.push_back({b, e});
  return out;
}

// Tables of instances with these entry counts (0: id not allocated), entries grouped by id.
ShadelGpuTables tablesWith(std::initializer_list<uint32_t> entryCounts) {
  ShadelGpuTables t;
  for (const uint32_t n : entryCounts) {
    const auto id = uint32_t(t.instances.size());
    t.instances.push_back({0, n ? 1u : 0u, 0, uint32_t(t.ownedEntries.size())});
    for (uint32_t k = 0; k < n; ++k) t.ownedEntries.push_back({k, id, 0, 0});
  }
  return t;
}

TEST(LiveEntrySpans, EachInstanceOwnsTheRunUpToTheNextAllocatedOne) {
  const auto runs = ownedEntryRuns(tablesWith({4, 0, 10, 1}));
  EXPECT_EQ(runs, spans({{0, 4}, {0, 0}, {4, 14}, {14, 15}}));
}

TEST(LiveEntrySpans, CulledObjectsEntriesAreLeftOut) {
  // The cull-offscreen layout: two visible objects first, ten off screen after them.
  const auto runs = ownedEntryRuns(tablesWith({0, 0, 100, 100, 100, 100, 100, 100, 100, 100, 100, 100, 100, 100}));
  const std::vector<uint32_t> visible{2, 3};
  EXPECT_EQ(liveEntrySpans(runs, visible), spans({{0, 200}}));
  EXPECT_EQ(entriesIn(liveEntrySpans(runs, visible)), 200u);
  // Scattered ones give a run each; a forward object (no entries) none.
  const std::vector<uint32_t> scattered{13, 2, 7, 0, 8};
  EXPECT_EQ(liveEntrySpans(runs, scattered), spans({{0, 100}, {500, 700}, {1100, 1200}}));
}

TEST(LiveEntrySpans, NothingLiveGivesNoSpan) {
  const auto runs = ownedEntryRuns(tablesWith({3, 5}));
  EXPECT_TRUE(liveEntrySpans(runs, {}).empty());
  const std::vector<uint32_t> unallocated{7};  // past the table: ignored
  EXPECT_TRUE(liveEntrySpans(runs, unallocated).empty());
  EXPECT_TRUE(liveEntrySpans({}, unallocated).empty());
  EXPECT_EQ(entriesIn({}), 0u);
}

TEST(LiveEntrySpans, TooManyRunsAreJoinedAcrossTheSmallestGaps) {
  // Runs of 10 entries with gaps 10, 30, 20 between them.
  const auto runs = spans({{0, 10}, {20, 30}, {60, 70}, {90, 100}});
  const std::vector<uint32_t> all{0, 1, 2, 3};
  EXPECT_EQ(liveEntrySpans(runs, all, 4).size(), 4u);
  EXPECT_EQ(liveEntrySpans(runs, all, 3), spans({{0, 30}, {60, 70}, {90, 100}}));
  EXPECT_EQ(liveEntrySpans(runs, all, 2), spans({{0, 30}, {60, 100}}));
  EXPECT_EQ(liveEntrySpans(runs, all, 1), spans({{0, 100}}));
}

TEST(LiveEntrySpans, AnObjectStaysLiveOneFrameAfterItIsCulled) {
  // It still holds stored chunks that frame; the frame's allocate frees them all.
  LiveInstances live;
  const std::vector<uint32_t> both{1, 4}, one{4}, none{};
  EXPECT_EQ(live.next(both), (std::vector<uint32_t>{1, 4}));
  EXPECT_EQ(live.next(one), (std::vector<uint32_t>{1, 4}));  // 1 culled: still holds storage
  EXPECT_EQ(live.next(one), (std::vector<uint32_t>{4}));     // freed last frame: left out
  EXPECT_EQ(live.next(none), (std::vector<uint32_t>{4}));
  EXPECT_EQ(live.next(none), (std::vector<uint32_t>{}));
  EXPECT_EQ(live.next(both), (std::vector<uint32_t>{1, 4}));  // back on screen
}

}  // namespace
}  // namespace sg::shadel
