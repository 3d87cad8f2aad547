// Triangle-ID maps that share one buffer: sizing them down to fit.
#include <gtest/gtest.h>

#include <decoupled/id_map_budget.hpp>

namespace sg::plugins {
namespace {

TEST(IdMapBudget, TexelsSumEveryLevel) {
  EXPECT_EQ(idMapTexels(64, 8), 64u * 64 + 32 * 32 + 16 * 16 + 8 * 8);
  EXPECT_EQ(idMapTexels(8, 8), 64u);
}

TEST(IdMapBudget, SizesThatFitAreKept) {
  const std::vector<uint32_t> wanted{512, 256, 64};
  const uint64_t total = idMapTexels(512, 8) + idMapTexels(256, 8) + idMapTexels(64, 8);
  EXPECT_EQ(fitIdMapSizes(wanted, total, 8, 64), wanted);
}

TEST(IdMapBudget, LargestAreHalvedUntilTheyFit) {
  // 123 maps of 512² (MetalRoughSpheresNoTextures) in a 128 MiB buffer.
  const std::vector<uint32_t> wanted(123, 512);
  const uint64_t budget = (uint64_t(128) << 20) / 4;
  const auto sizes = fitIdMapSizes(wanted, budget, 8, 64);
  uint64_t total = 0;
  for (const uint32_t size : sizes) total += idMapTexels(size, 8);
  EXPECT_LE(total, budget);
  // Halving stops as soon as they fit: sizes differ by at most one halving.
  const auto [lo, hi] = std::minmax_element(sizes.begin(), sizes.end());
  EXPECT_EQ(*hi, 512u);
  EXPECT_EQ(*lo, 256u);
}

TEST(IdMapBudget, NeverBelowTheFloor) {
  const auto sizes = fitIdMapSizes({1024, 128}, 10, 8, 64);
  EXPECT_EQ(sizes, (std::vector<uint32_t>{64, 64}));
}

}  // namespace
}  // namespace sg::plugins
