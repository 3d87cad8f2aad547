#pragma once
// The global shade-space adjuster (paper §"Running out of space"): a
// fractional level bias for every decoupled object, raised when the last
// frame's allocation came close to the shade storage's capacity and relaxed
// when it empties, with hysteresis so a steady scene gets a steady bias.
//
// Counters arrive a frame or more late. Each readback carries the bias its
// frame was rendered with, and the adjuster computes the bias that frame
// *should* have had; an old readback therefore repeats the same answer
// instead of pushing the bias further (no overshoot from latency).
#include <cstdint>

namespace sg::plugins {

struct ShadeSpaceCounters {
  float bias = 0.0f;               // the bias the frame was rendered with
  uint64_t chunksRequested = 0;    // chunks marked visible (allocated + overflowed)
  uint64_t chunksCapacity = 0;     // chunks the shade storage holds
  uint64_t overflowChunks = 0;     // chunks that found their storage partition full
};

struct ShadeSpaceAdjusterOptions {
  float target = 0.80f;    // aim for this fraction of capacity
  float high = 0.92f;      // above: raise the bias at once
  float low = 0.55f;       // below: relax the bias gradually
  float relaxStep = 0.05f;  // at most this much finer per frame
  float overflowStep = 0.25f;  // coarser, at least, after a frame that overflowed (partitions fill unevenly)
  float minBias = 0.0f;     // the finest the adjuster may go (a user's quality setting)
  float maxBias = 8.0f;
};

class ShadeSpaceAdjuster {
 public:
  explicit ShadeSpaceAdjuster(ShadeSpaceAdjusterOptions options = {}) : options_(options), bias_(options.minBias) {}
  // Feeds one frame's counters; returns the bias for the next frame.
  float update(const ShadeSpaceCounters& counters);
  float bias() const { return bias_; }

 private:
  ShadeSpaceAdjusterOptions options_;
  float bias_;
};

}  // namespace sg::plugins
