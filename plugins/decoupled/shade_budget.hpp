#pragma once
// Budget mode (--shade-budget MS): there are no periodic shade frames. Every
// raster frame shades what it must (the fill: chunks without stored shading,
// so composite never misses) and then the stalest of the chunks it could
// reuse, as many as the budget's layer-shade time affords; the rest stay
// stale. The GPU picks by age against one limit (reuse.glsl): a reusable
// chunk whose shading is older than `limit` raster frames is reshaded, and
// of those exactly `limit` old the `fraction` a hash of their place picks.
// This class sets that limit for the next frame from this frame's counters
// (the reusable chunks by age, the fill) and the measured layer-shade cost
// per chunk.
#include <cstdint>
#include <span>

namespace sg::plugins {

// Before anything is measured: lavapipe on 2 cores shades a chunk (64 shadels,
// glTF PBR, three lights) in about 7 us; start a little pessimistic.
inline constexpr double kInitialMsPerChunk = 0.01;
// The limit that reuses everything, whatever its age.
inline constexpr uint32_t kReuseAnyAge = 0xFFFFFFFFu;
inline constexpr uint32_t kWholeFraction = 65536;  // staleAgeFraction: all chunks of the limit's age

struct StaleAgeLimit {
  uint32_t limit = kReuseAnyAge;
  uint32_t fraction = 0;  // of kWholeFraction
};

class ShadeBudget {
 public:
  explicit ShadeBudget(double budgetMs, double msPerChunk = kInitialMsPerChunk)
      : budgetMs_(budgetMs), msPerChunk_(msPerChunk) {}

  // A frame's layer-shade GPU time and the chunks its layers shaded: updates
  // the cost per chunk (a running average; frames shading few chunks, where
  // dispatch overhead dominates, are ignored).
  void observeCost(double layerShadeMs, uint64_t chunksShaded);
  // The next frame's age limit from this frame's: the chunks it filled, the
  // reusable ones by age (bins 0..n-2 exact, the last "n-1 or more") and the
  // limit it ran with. Every reusable chunk ages by one frame, what was shaded
  // this frame becomes one frame old; the limit is the lowest (oldest chunks
  // first) whose reshading fits in the budget left after a fill like this one.
  // `expectedFill`: what the next frame will have to fill (this frame's fill, but not after a first frame that shaded everything).
  StaleAgeLimit nextAgeLimit(uint64_t filledChunks, uint64_t expectedFill, std::span<const uint32_t> ageChunks,
                             StaleAgeLimit current) const;

  double budgetMs() const { return budgetMs_; }
  double msPerChunk() const { return msPerChunk_; }
  // Chunks the budget pays for in a frame.
  uint64_t budgetChunks() const;

 private:
  double budgetMs_;
  double msPerChunk_;
};

}  // namespace sg::plugins
