// The shade frame running past its raster frame (frames in flight, issue 15),
// on the device with validation and synchronization validation on: rate 4,
// two frames in flight, the shade frame's layer passes after composite as the
// frame's tail on async compute, read by the next raster frames. A static
// camera gives rate 1's images; a moving camera with a moving object misses
// nothing for 30 frames.
#include <gtest/gtest.h>

#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;

plugins::DecoupledSettings settingsAt(uint32_t rate, bool overlap) {
  return {.storageChunks = 8192, .fixedBias = 0.0f, .shadeRate = rate, .overlap = overlap};
}


render::FrameResult renderInFlight(Session& s, const scene::Camera& camera) {
  return s.renderer().render({.width = kSize, .height = kSize, .cameraOverride = camera, .framesInFlight = 2});
}

bool hasTailPass(const graph::CompiledPlan& plan, const std::string& name) {
  for (const auto& batch : plan.batches)
    for (const auto p : plan.passesOf(batch))
      if (batch.tail && plan.passes[p.index].name == name) return true;
  return false;
}

TEST(ShadeFrameOverlap, ShadeFrameIsTheTailOfItsRasterFrame) {
  Session s(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, settingsAt(4, true));
  const auto plan = s.plan(kSize, panCamera(0, 0.1f));  // frame 0: a shade frame
  EXPECT_TRUE(hasTailPass(plan, "shade-frame-work"));
  EXPECT_TRUE(hasTailPass(plan, "shade-frame layer-shade"));
  EXPECT_FALSE(hasTailPass(plan, "composite"));
  const auto next = s.plan(kSize, panCamera(0, 0.1f));  // frame 1: raster only
  EXPECT_FALSE(hasTailPass(next, "shade-frame layer-shade"));
}

// Static camera: the raster frames reuse what the shade frames (and the first
// frame's fill) stored, so every frame shows rate 1's image.
TEST(ShadeFrameOverlap, StaticCameraGivesTheImagesOfRate1) {
  const auto scene = scene::makeDefaultScene(64);
  Session one(scene, scene::ShadingMode::Decoupled, settingsAt(1, false));
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(4, true));
  for (int frame = 0; frame < 9; ++frame) {
    const auto expected = one.render(kSize, panCamera(0, 0.1f));
    const auto image = renderInFlight(n, panCamera(0, 0.1f)).image;
    const auto diff = image::compareRgba8(expected.rgba8, image.rgba8);
    EXPECT_EQ(diff.maxAbs, 0) << "frame " << frame << ": PSNR " << diff.psnr;
    const auto st = n.stats();
    EXPECT_EQ(st.counters.compositeMisses, 0u) << "frame " << frame;
    if (frame > 0) {
      EXPECT_EQ(st.counters.chunksShaded, 0u) << "frame " << frame << ": the raster frame shades nothing";
    }
  }
  EXPECT_EQ(n.stats().shadeFrames, 3u);
  n.renderer().finishFrames();
}

// 30 frames, two in flight, a panning camera and the gold sphere moving: no
// composite miss in any frame, validation (sync included) clean.
TEST(ShadeFrameOverlap, MovingCameraAndObjectMissNothing) {
  auto scene = scene::makeDefaultScene(64);
  uint32_t sphere = ~0u;
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == "gold sphere") sphere = i;
  ASSERT_NE(sphere, ~0u);
  const glm::mat4 start = scene.instances[sphere].world;
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(4, true));
  for (int frame = 0; frame < 30; ++frame) {
    n.renderer().setObjectTransform(sphere, glm::translate(glm::mat4(1.0f), {0.02f * float(frame), 0.0f, 0.0f}) * start);
    renderInFlight(n, panCamera(frame, 0.1f));
    const auto st = n.stats();
    EXPECT_EQ(st.counters.compositeMisses, 0u) << "frame " << frame;
    EXPECT_EQ(st.counters.overflowChunks, 0u) << "frame " << frame;
  }
  const auto tails = n.renderer().finishFrames();
  EXPECT_FALSE(tails.empty()) << "shade frames ran as tails";
  EXPECT_GT(n.stats().chunksReused, 0u);
}

}  // namespace
}  // namespace sg::test
