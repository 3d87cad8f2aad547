// live-entry-blocks' host side: how many candidate blocks of 64 owned entries
// the live spans give (each span cut on its own), and when there are too many
// for the blocks' dispatches (the passes then dispatch the spans).
#include <gtest/gtest.h>

#include <vector>

#include <live-entry-blocks/live_entry_blocks.hpp>

namespace sg::test {
namespace {

using shader::SgEntrySpan;

TEST(LiveEntryBlocks, EachSpanIsCutInBlocksOf64) {
  const std::vector<SgEntrySpan> spans{{0, 100, 0}, {200, 264, 0}, {300, 301, 0}};
  EXPECT_EQ(passes::entryBlockCandidates(spans), 2u + 1u + 1u);
  const std::vector<SgEntrySpan> withEmpty{{0, 64, 0}, {70, 70, 0}};
  EXPECT_EQ(passes::entryBlockCandidates(withEmpty), 1u);
  EXPECT_EQ(passes::entryBlockCandidates({}), 0u);
}

TEST(LiveEntryBlocks, NoneWhenTheDispatchesCannotTakeThem) {
  // 32-entry passes dispatch two workgroups per block, at most 65535.
  const std::vector<SgEntrySpan> fits{{0, 64u * 32767u, 0}};
  EXPECT_EQ(passes::entryBlockCandidates(fits), 32767u);
  const std::vector<SgEntrySpan> tooMany{{0, 64u * 32768u, 0}};
  EXPECT_EQ(passes::entryBlockCandidates(tooMany), 0u);
  // More spans than the pass's push constants hold.
  std::vector<SgEntrySpan> spans;
  for (uint32_t i = 0; i < shader::kMaxBlockSpans + 1; ++i) spans.push_back({i * 100, i * 100 + 10, 0});
  EXPECT_EQ(passes::entryBlockCandidates(spans), 0u);
  spans.pop_back();
  EXPECT_EQ(passes::entryBlockCandidates(spans), shader::kMaxBlockSpans);
}

}  // namespace
}  // namespace sg::test
