// The per-entry passes visit only the live objects' remap entries (shaded now
// or still holding stored chunks): along a path that turns away from a row of
// decoupled spheres and back, every frame is the same image, with the same
// shade counters, as when they visit every allocated entry, at shade rates 1
// and 3 (shading kept between frames: a sphere coming back must not find
// chunks stored before it left). And the span must leave entries out.
#include <gtest/gtest.h>

#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

// The default courtyard with a row of spheres behind the default camera's back.
scene::Scene courtyardWithSpheresBehind() {
  return courtyardWithSphereRow("sphere behind", 4, {-3.0f, 1.0f, 10.0f}, scene::ShadingMode::Decoupled);
}

scene::Camera looking(glm::vec3 target) { return lookAtCamera({0.0f, 2.0f, 6.0f}, target); }

class LiveEntrySpans : public ::testing::TestWithParam<uint32_t> {};

TEST_P(LiveEntrySpans, SameImagesAndCountersAsOverEveryEntry) {
  const scene::Scene scene = courtyardWithSpheresBehind();
  const plugins::DecoupledSettings settings{.storageChunks = 16384, .fixedBias = 0.0f, .shadeRate = GetParam()};
  plugins::DecoupledSettings everyEntry = settings;
  everyEntry.liveEntrySpans = false;
  Session live(scene, scene::ShadingMode::Decoupled, settings), all(scene, scene::ShadingMode::Decoupled, everyEntry);
  const scene::Camera away = looking({0.0f, 1.0f, -4.0f}), toward = looking({0.0f, 1.0f, 10.0f});
  // Away: the spheres are culled; toward: the courtyard is.
  const std::vector<scene::Camera> path{away, toward, away, away, toward, toward, away};
  std::vector<uint32_t> liveEntries;
  for (size_t f = 0; f < path.size(); ++f) {
    const auto a = live.render(96, path[f]);
    const auto b = all.render(96, path[f]);
    const auto diff = image::compareRgba8(a.rgba8, b.rgba8);
    EXPECT_EQ(diff.maxAbs, 0) << "frame " << f << ": mean |d| " << diff.meanAbs;
    const auto s = live.stats(), t = all.stats();
    EXPECT_EQ(s.counters.chunksMarked, t.counters.chunksMarked) << "frame " << f;
    EXPECT_EQ(s.counters.chunksAllocated, t.counters.chunksAllocated) << "frame " << f;
    EXPECT_EQ(s.counters.chunksShaded, t.counters.chunksShaded) << "frame " << f;
    EXPECT_EQ(s.counters.chunksReused, t.counters.chunksReused) << "frame " << f;
    EXPECT_EQ(s.counters.overflowChunks, 0u) << "frame " << f;
    EXPECT_EQ(t.liveEntries, t.ownedEntries) << "frame " << f;
    EXPECT_GT(s.counters.chunksMarked, 0u) << "frame " << f;
    liveEntries.push_back(s.liveEntries);
  }
  const uint32_t owned = live.stats().ownedEntries;
  // Frame 2 turns away: the spheres still hold their chunks and are visited
  // (their chunks freed); in frame 3 they are left out.
  EXPECT_LT(liveEntries[3], liveEntries[2]);
  EXPECT_LT(liveEntries[3], owned);
  EXPECT_LT(liveEntries[5], owned);  // looking at the spheres, the courtyard's entries are left out
}

INSTANTIATE_TEST_SUITE_P(ShadeRates, LiveEntrySpans, ::testing::Values(1u, 3u),
                         [](const auto& rate) { return "rate" + std::to_string(rate.param); });

}  // namespace
}  // namespace sg::test
