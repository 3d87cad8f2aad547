// The adjuster against a model of a scene: chunks requested at bias b are
// demand0 / 4^b (each level of bias quarters the shadels), reported with a
// frame of latency, as the GPU readback does.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>

#include <decoupled/shade_space_adjuster.hpp>

namespace sg::plugins {
namespace {

struct Simulation {
  double demandAtZero;  // chunks the scene wants at bias 0
  uint64_t capacity;
  int latency = 1;
};

std::vector<float> simulate(const Simulation& s, int frames, ShadeSpaceAdjuster& adjuster) {
  std::deque<ShadeSpaceCounters> inFlight;
  std::vector<float> biases;
  float bias = adjuster.bias();
  for (int f = 0; f < frames; ++f) {
    biases.push_back(bias);
    const auto requested = uint64_t(s.demandAtZero / std::pow(4.0, bias));
    inFlight.push_back({bias, requested, s.capacity});
    if (int(inFlight.size()) > s.latency) {
      bias = adjuster.update(inFlight.front());
      inFlight.pop_front();
    }
  }
  return biases;
}

TEST(ShadeSpaceAdjuster, OverflowSettlesWithinTenFramesAndStaysSteady) {
  ShadeSpaceAdjuster adjuster;
  const auto biases = simulate({.demandAtZero = 100000, .capacity = 12000}, 40, adjuster);
  EXPECT_GT(biases[10], 1.0f);  // raised: 100000 chunks cannot fit in 12000
  for (size_t f = 10; f + 1 < biases.size(); ++f)
    EXPECT_LT(std::abs(biases[f + 1] - biases[f]), 0.01f) << "frame " << f;
  // Settled where the requested chunks fit, with the high watermark not crossed.
  const double use = 100000 / std::pow(4.0, biases.back()) / 12000;
  EXPECT_LE(use, 0.92);
  EXPECT_GE(use, 0.55);
}

TEST(ShadeSpaceAdjuster, LatencyDoesNotOvershoot) {
  ShadeSpaceAdjuster adjuster;
  const auto biases = simulate({.demandAtZero = 100000, .capacity = 12000, .latency = 3}, 40, adjuster);
  const float settled = biases.back();
  for (float b : biases) EXPECT_LE(b, settled + 1e-4f);
}

TEST(ShadeSpaceAdjuster, RelaxesWhenStorageEmptiesButNotPastTheFinestBias) {
  ShadeSpaceAdjuster adjuster;
  simulate({.demandAtZero = 100000, .capacity = 12000}, 20, adjuster);
  const float raised = adjuster.bias();
  ASSERT_GT(raised, 1.0f);
  // The scene shrinks (the camera moved away): demand drops 100x.
  const auto biases = simulate({.demandAtZero = 1000, .capacity = 12000}, 200, adjuster);
  EXPECT_LT(biases[5], raised);                         // it relaxes...
  EXPECT_GE(biases[1] - biases[2], -1e-6f);             // ...monotonically...
  EXPECT_LE(biases[1] - biases[2], 0.05f + 1e-6f);      // ...a step at a time
  EXPECT_FLOAT_EQ(biases.back(), 0.0f);                 // down to the finest allowed
}

TEST(ShadeSpaceAdjuster, OverflowBelowTheWatermarkStillRaises) {
  ShadeSpaceAdjuster adjuster;
  const float b = adjuster.update({.bias = 0.0f, .chunksRequested = 500, .chunksCapacity = 1000, .overflowChunks = 64});
  EXPECT_GE(b, 0.25f);
}

TEST(ShadeSpaceAdjuster, HoldsInsideTheHysteresisBand) {
  ShadeSpaceAdjuster adjuster;
  EXPECT_FLOAT_EQ(adjuster.update({.bias = 0.0f, .chunksRequested = 700, .chunksCapacity = 1000}), 0.0f);
  ShadeSpaceAdjuster raised;
  raised.update({.bias = 0.0f, .chunksRequested = 4000, .chunksCapacity = 1000});
  const float b = raised.bias();
  EXPECT_FLOAT_EQ(raised.update({.bias = b, .chunksRequested = 700, .chunksCapacity = 1000}), b);
}

}  // namespace
}  // namespace sg::plugins
