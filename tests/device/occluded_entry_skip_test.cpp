// The per-entry passes skip the entries of decoupled objects the occlusion
// cull hid this frame and last frame (live-entry-blocks): along a path where
// a row of decoupled spheres stays hidden behind the courtyard's back wall,
// shows over it, hides again and comes back, every frame is the same image,
// with the same shade counters, as without the skip, at shade rates 1 and 3
// (shading kept between frames: a sphere coming back must not find chunks
// stored before it hid). And the skip must happen: fewer entries visited
// once the spheres have been hidden for two frames, none fewer before.
#include <gtest/gtest.h>

#include <string>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr int kSpheres = 6;

// The courtyard with a row of spheres behind its back wall; 256-texel
// textures give each sphere 24 owned entries, so the row fills whole blocks
// of 64 (a block is visited when any of its objects is).
scene::Scene courtyardWithHiddenSpheres() {
  return courtyardWithSphereRow("hidden sphere", kSpheres, {-5.0f, 1.0f, -10.5f}, scene::ShadingMode::Decoupled, 256);
}

class OccludedEntrySkip : public ::testing::TestWithParam<uint32_t> {};

TEST_P(OccludedEntrySkip, SameImagesAndCountersAsWithoutAlongAHideAndReturnPath) {
  const scene::Scene scene = courtyardWithHiddenSpheres();
  const plugins::DecoupledSettings settings{.storageChunks = 16384, .fixedBias = 0.0f, .shadeRate = GetParam()};
  plugins::DecoupledSettings noSkip = settings;
  noSkip.skipOccludedEntries = false;
  Session skip(scene, scene::ShadingMode::Decoupled, settings), all(scene, scene::ShadingMode::Decoupled, noSkip);
  const scene::Camera hidden = lookAtCamera({1.5f, 3.2f, 8.5f}, {0.0f, 1.0f, -4.0f});
  const scene::Camera over = lookAtCamera({1.5f, 9.0f, 8.5f}, {0.0f, 1.0f, -4.0f});        // the spheres show over the wall
  const scene::Camera behind = lookAtCamera({0.0f, 2.0f, -16.0f}, {0.0f, 1.0f, -10.0f});  // behind the wall, facing them
  const std::vector<scene::Camera> path{hidden, hidden, hidden, over, over, hidden, hidden, behind, hidden, hidden};
  const size_t firstSphere = scene.instances.size() - kSpheres;
  std::vector<uint32_t> visited, visitedAll;
  std::vector<bool> spheresCulled;
  for (size_t f = 0; f < path.size(); ++f) {
    const auto a = skip.renderer().render({.width = 160, .height = 120, .cameraOverride = path[f]}).image;
    const auto b = all.renderer().render({.width = 160, .height = 120, .cameraOverride = path[f]}).image;
    const auto diff = image::compareRgba8(a.rgba8, b.rgba8);
    EXPECT_EQ(diff.maxAbs, 0) << "frame " << f << ": mean |d| " << diff.meanAbs;
    const auto s = skip.stats(), t = all.stats();
    EXPECT_EQ(s.counters.chunksMarked, t.counters.chunksMarked) << "frame " << f;
    EXPECT_EQ(s.counters.chunksAllocated, t.counters.chunksAllocated) << "frame " << f;
    EXPECT_EQ(s.counters.chunksShaded, t.counters.chunksShaded) << "frame " << f;
    EXPECT_EQ(s.counters.chunksReused, t.counters.chunksReused) << "frame " << f;
    EXPECT_EQ(s.counters.overflowChunks, t.counters.overflowChunks) << "frame " << f;
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << f;
    EXPECT_EQ(t.counters.compositeMisses, 0u) << "frame " << f;
    EXPECT_GT(s.counters.chunksMarked, 0u) << "frame " << f;
    // Without the skip the passes visit the whole live spans.
    EXPECT_EQ(t.visitedEntries, t.liveEntries) << "frame " << f;
    EXPECT_LE(s.visitedEntries, s.liveEntries) << "frame " << f;
    visited.push_back(s.visitedEntries);
    visitedAll.push_back(t.visitedEntries);
    const auto visible = skip.renderer().culling().lastVisible();
    const auto& draws = skip.renderer().gpuScene().draws();
    bool culled = true;
    for (size_t d = 0; d < draws.size(); ++d)
      if (draws[d].instance >= firstSphere) culled = culled && !visible[d];
    spheresCulled.push_back(culled);
  }
  // The path does hide them (not in the first frame: no depth yet to test against), and shows them.
  for (size_t f : {1u, 2u, 5u, 6u, 8u, 9u}) EXPECT_TRUE(spheresCulled[f]) << "frame " << f;
  for (size_t f : {0u, 3u, 4u, 7u}) EXPECT_FALSE(spheresCulled[f]) << "frame " << f;
  // Hidden two frames running: their entries are left out. The first frame
  // they are hidden in visits them (their chunks are freed).
  for (size_t f : {2u, 6u, 9u}) EXPECT_LT(visited[f], visitedAll[f]) << "frame " << f;
  for (size_t f : {0u, 1u, 3u, 4u, 5u, 7u, 8u}) EXPECT_EQ(visited[f], visitedAll[f]) << "frame " << f;
}

// Frames without occlusion culling draw every object: the skip leaves
// nothing out in them nor in the culled frame after (every object was drawn
// last frame, its chunks must be freed).
TEST(OccludedEntrySkip, VisitsEverythingWithoutCullingAndTheFrameAfter) {
  const scene::Scene scene = courtyardWithHiddenSpheres();
  const plugins::DecoupledSettings settings{.storageChunks = 16384, .fixedBias = 0.0f};
  plugins::DecoupledSettings noSkip = settings;
  noSkip.skipOccludedEntries = false;
  Session skip(scene, scene::ShadingMode::Decoupled, settings), all(scene, scene::ShadingMode::Decoupled, noSkip);
  const scene::Camera hidden = lookAtCamera({1.5f, 3.2f, 8.5f}, {0.0f, 1.0f, -4.0f});
  const std::vector<bool> culling{true, true, true, false, true, true};
  std::vector<uint32_t> visited, visitedAll;
  for (size_t f = 0; f < culling.size(); ++f) {
    const render::RenderSettings options{.width = 160, .height = 120, .cameraOverride = hidden, .occlusionCulling = culling[f]};
    const auto a = skip.renderer().render(options).image;
    const auto b = all.renderer().render(options).image;
    EXPECT_EQ(image::compareRgba8(a.rgba8, b.rgba8).maxAbs, 0) << "frame " << f;
    EXPECT_EQ(skip.stats().counters.chunksMarked, all.stats().counters.chunksMarked) << "frame " << f;
    visited.push_back(skip.stats().visitedEntries);
    visitedAll.push_back(all.stats().visitedEntries);
  }
  EXPECT_LT(visited[2], visitedAll[2]);  // hidden in frames 1 and 2
  EXPECT_EQ(visited[3], visitedAll[3]);  // unculled: every sphere drawn
  EXPECT_EQ(visited[4], visitedAll[4]);  // drawn last frame
  EXPECT_LT(visited[5], visitedAll[5]);
}

INSTANTIATE_TEST_SUITE_P(ShadeRates, OccludedEntrySkip, ::testing::Values(1u, 3u),
                         [](const auto& rate) { return "rate" + std::to_string(rate.param); });

}  // namespace
}  // namespace sg::test
