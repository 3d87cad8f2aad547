#include "shade_budget.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sg::plugins {
namespace {
constexpr uint64_t kMinChunksToMeasure = 64;
constexpr double kCostSmoothing = 0.25;  // weight of the newest frame in the running average
}  // namespace

void ShadeBudget::observeCost(double layerShadeMs, uint64_t chunksShaded) {
  if (chunksShaded < kMinChunksToMeasure || !(layerShadeMs > 0.0)) return;
  const double measured = layerShadeMs / double(chunksShaded);
  msPerChunk_ += kCostSmoothing * (measured - msPerChunk_);
}

uint64_t ShadeBudget::budgetChunks() const {
  return msPerChunk_ > 0.0 ? uint64_t(std::floor(budgetMs_ / msPerChunk_)) : 0;
}

StaleAgeLimit ShadeBudget::nextAgeLimit(uint64_t filledChunks, uint64_t expectedFill,
                                        std::span<const uint32_t> ageChunks, StaleAgeLimit current) const {
  const size_t bins = ageChunks.size();
  if (bins < 2) return {};
  // Next frame's reusable chunks by age (if they stay visible): what was
  // reshaded this frame is one frame old then, the rest one frame older.
  std::vector<uint64_t> next(bins, 0);
  next[1] += filledChunks;
  for (size_t age = 0; age < bins; ++age) {
    const uint64_t count = ageChunks[age];
    if (age == current.limit) {  // the fraction picked was reshaded
      const uint64_t part = count * current.fraction / kWholeFraction;
      next[1] += part;
      next[std::min(age + 1, bins - 1)] += count - part;
      continue;
    }
    next[age > current.limit ? 1 : std::min(age + 1, bins - 1)] += count;
  }
  const uint64_t budget = budgetChunks();
  const uint64_t spare = budget > expectedFill ? budget - expectedFill : 0;
  // The oldest first: every chunk older than the limit, and of the limit's
  // age the fraction that still fits.
  uint64_t older = 0;
  for (size_t age = bins - 1; age >= 1; --age) {
    if (older + next[age] > spare) {
      const uint64_t fits = spare - older;
      return {uint32_t(age), uint32_t(fits * kWholeFraction / next[age])};
    }
    older += next[age];
  }
  return {1, kWholeFraction};  // everything reusable fits
}

}  // namespace sg::plugins
