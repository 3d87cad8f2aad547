// Budget mode and the staleness stat on the device (validation on): whatever
// the budget, what a frame marks without stored shading is filled (no
// composite miss); what the budget affords of the rest is reshaded oldest
// first; the oldest shading composite reads is counted (staleMaxAge).
#include <gtest/gtest.h>

#include <string>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;

// A fixed cost per chunk (no timings are fed back): the budget in chunks is budgetMs / 0.01.
plugins::DecoupledSettings budgetOf(double ms) {
  return {.storageChunks = 8192, .fixedBias = 0.0f, .shadeBudgetMs = ms, .budgetMsPerChunk = 0.01};
}


// Shade rate 4, static camera: the oldest shading read is 0, 1, 2, 3 frames
// old through a shade period, then 0 again on the next shade frame.
TEST(StaleAge, CountsFramesSinceTheShadeFrame) {
  Session n(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled,
            {.storageChunks = 8192, .fixedBias = 0.0f, .shadeRate = 4});
  for (int frame = 0; frame < 6; ++frame) {
    n.render(kSize, panCamera(0));
    EXPECT_EQ(n.stats().counters.staleMaxAge, uint32_t(frame % 4)) << "frame " << frame;
  }
}

// A budget of one chunk a frame while the camera pans: every frame fills what
// it uncovers (more than the budget: the fill is never cut), misses nothing,
// and leaves the rest stale, older and older.
TEST(ShadeBudget, MissingChunksAreFilledWhateverTheBudget) {
  Session n(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, budgetOf(0.01));
  uint32_t lastAge = 0;
  for (int frame = 0; frame < 8; ++frame) {
    n.render(kSize, panCamera(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    EXPECT_EQ(s.shadeFrame, frame == 0) << "budget mode has no shade frames after the first";
    if (frame == 0) continue;
    EXPECT_GT(s.counters.chunksReused, 0u) << "frame " << frame << ": left stale";
    EXPECT_LE(s.counters.chunksRefreshed, 4u) << "frame " << frame << ": a chunk's budget (the hash picks about that many)";
    lastAge = s.counters.staleMaxAge;
  }
  EXPECT_GE(lastAge, 5u) << "shading from the first frames is still read";
  EXPECT_GT(n.stats().chunksFilled, 0u) << "the pan uncovered chunks, and they were filled";
}

// A budget larger than the scene: every reusable chunk is reshaded every frame
// (nothing read is older than this frame), so the images are rate 1's.
TEST(ShadeBudget, AmpleBudgetShadesEverythingEveryFrame) {
  const auto scene = scene::makeDefaultScene(64);
  Session one(scene, scene::ShadingMode::Decoupled, {.storageChunks = 8192, .fixedBias = 0.0f});
  Session n(scene, scene::ShadingMode::Decoupled, budgetOf(1000.0));
  for (int frame = 0; frame < 4; ++frame) {
    const auto expected = one.render(kSize, panCamera(frame));
    const auto image = n.render(kSize, panCamera(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u);
    if (frame == 0) continue;
    EXPECT_EQ(s.counters.chunksReused, 0u) << "frame " << frame;
    EXPECT_EQ(s.counters.staleMaxAge, 0u) << "frame " << frame;
    EXPECT_GT(s.counters.chunksRefreshed, 0u) << "frame " << frame;
    EXPECT_EQ(image::compareRgba8(expected.rgba8, image.rgba8).maxAbs, 0) << "frame " << frame;
  }
}

// A static camera and a budget of about a quarter of the visible chunks: each
// frame reshades about that many (the chunks exactly at the age limit are
// picked by a hash, so the count is approximate), the oldest first, so no
// shading read gets much older than four frames (it would grow without
// bound if the choice were not by age).
TEST(ShadeBudget, StalestChunksAreReshadedFirst) {
  Session probe(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, budgetOf(0.01));
  probe.render(kSize, panCamera(0));
  const uint32_t visible = probe.stats().counters.chunksAllocated;
  ASSERT_GT(visible, 40u);
  const double quarterMs = 0.01 * double(visible / 4);
  Session n(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, budgetOf(quarterMs));
  uint32_t refreshed = 0, frames = 0;
  for (int frame = 0; frame < 12; ++frame) {
    n.render(kSize, panCamera(0));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u);
    if (frame < 2) continue;
    EXPECT_GT(s.counters.chunksRefreshed, 0u) << "frame " << frame;
    EXPECT_LT(s.counters.chunksRefreshed, visible) << "frame " << frame << ": never everything";
    EXPECT_GT(s.counters.chunksReused, 0u) << "frame " << frame << ": the rest left stale";
    if (frame >= 6) { EXPECT_LE(s.counters.staleMaxAge, 6u) << "frame " << frame; }
    refreshed += s.counters.chunksRefreshed;
    ++frames;
  }
  // The budget is met on average (one frame of latency, whole age bins): within 2x of it.
  EXPECT_LE(refreshed / frames, visible / 2) << "about the budget on average";
}

}  // namespace
}  // namespace sg::test
