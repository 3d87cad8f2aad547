// Shading kept between raster frames (--shade-rate N, issue 15) on the device,
// validation and synchronization validation on: a static camera at rate N
// renders exactly what rate 1 does while reusing; what a frame marks without
// valid shading (an object switched to decoupled, a camera pan, a bias step,
// a resize) is shaded in that frame, with no composite miss; a moved object
// or one given another material is reshaded, not reused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;
// Ample storage and a fixed bias: these compare reuse, not the adjuster.
plugins::DecoupledSettings settingsAt(uint32_t rate) {
  return {.storageChunks = 8192, .fixedBias = 0.0f, .shadeRate = rate};
}


void expectSameImage(const gpu::HostImage& expected, const gpu::HostImage& actual, const std::string& what) {
  const auto diff = image::compareRgba8(expected.rgba8, actual.rgba8);
  EXPECT_EQ(diff.maxAbs, 0) << what << ": PSNR " << diff.psnr << " dB against rate 1";
}

class ShadeRate : public ::testing::TestWithParam<uint32_t> {};

// Static camera: every frame of rate N equals rate 1's, the frames between
// shade frames shade nothing and reuse every stored chunk.
TEST_P(ShadeRate, StaticCameraGivesTheImagesOfRate1) {
  const uint32_t rate = GetParam();
  const auto scene = scene::makeDefaultScene(64);
  Session one(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(rate));
  for (int frame = 0; frame < 6; ++frame) {
    const auto expected = one.render(kSize, panCamera(0));
    const auto image = n.render(kSize, panCamera(0));
    expectSameImage(expected, image, "frame " + std::to_string(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    EXPECT_EQ(s.shadeFrame, frame % rate == 0) << "frame " << frame;
    if (!s.shadeFrame) {
      EXPECT_EQ(s.counters.chunksShaded, 0u) << "frame " << frame << ": nothing changed, nothing to fill";
      EXPECT_EQ(s.counters.chunksReused, s.counters.chunksAllocated) << "frame " << frame;
    }
  }
  const auto s = n.stats();
  EXPECT_EQ(s.rasterFrames, 6u);
  EXPECT_EQ(s.shadeFrames, (6u + rate - 1) / rate);
  EXPECT_GT(s.chunksReused, 0u);
  EXPECT_EQ(one.stats().chunksReused, 0u) << "rate 1 shades every frame";
}

INSTANTIATE_TEST_SUITE_P(Rates, ShadeRate, ::testing::Values(2u, 8u),
                         [](const ::testing::TestParamInfo<uint32_t>& rate) {
                           return "Rate" + std::to_string(rate.param);
                         });

// The gold sphere turns decoupled at frame 3 (rate 8: not a shade frame). It
// has nothing stored: that frame shades it (the fill) and reuses the rest,
// misses nothing, and shows what rate 1 shows.
TEST(ShadeRateFill, ObjectAppearingBetweenShadeFramesIsShadedThatFrame) {
  auto scene = scene::makeDefaultScene(64);
  uint32_t sphere = ~0u;
  for (uint32_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == "gold sphere") sphere = i;
  ASSERT_NE(sphere, ~0u);
  Session one(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(8));
  for (Session* s : {&one, &n}) s->renderer().setObjectMode(sphere, scene::ShadingMode::Forward);
  for (int frame = 0; frame < 5; ++frame) {
    if (frame == 3)
      for (Session* s : {&one, &n}) s->renderer().setObjectMode(sphere, scene::ShadingMode::Decoupled);
    const auto expected = one.render(kSize, panCamera(0));
    const auto image = n.render(kSize, panCamera(0));
    expectSameImage(expected, image, "frame " + std::to_string(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    EXPECT_FALSE(frame > 0 && s.shadeFrame);
    if (frame == 3) {
      EXPECT_GT(s.counters.chunksShaded, 0u) << "the sphere is filled";
      EXPECT_GT(s.counters.chunksReused, 0u) << "the rest is reused";
      EXPECT_EQ(s.counters.chunksShaded + s.counters.chunksReused, s.counters.chunksAllocated);
    }
    if (frame == 4) { EXPECT_EQ(s.counters.chunksShaded, 0u) << "the sphere's shading is stored now"; }
  }
}

// A camera pan at rate 8: every frame uncovers and re-levels chunks, which are
// filled; nothing is missed; the chunks seen in both frames are reused.
TEST(ShadeRateFill, CameraPanMissesNothing) {
  Session n(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, settingsAt(8));
  uint64_t filledFrames = 0;
  for (int frame = 0; frame < 8; ++frame) {
    n.render(kSize, panCamera(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    EXPECT_EQ(s.counters.overflowChunks, 0u) << "frame " << frame;
    if (frame > 0) {
      EXPECT_GT(s.counters.chunksReused, 0u) << "frame " << frame;
      filledFrames += s.counters.chunksShaded > 0 ? 1 : 0;
    }
  }
  EXPECT_GT(filledFrames, 0u) << "a pan must uncover something";
  EXPECT_GT(n.stats().chunksFilled, 0u);
}

// A bias step to a coarser level between shade frames: the new level's chunks
// were never stored, so they are filled; the image is rate 1's at that bias.
TEST(ShadeRateInvalidation, BiasStepFillsTheNewLevel) {
  const auto scene = scene::makeDefaultScene(64);
  Session one(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(8));
  for (int frame = 0; frame < 4; ++frame) {
    if (frame == 2)
      for (Session* s : {&one, &n}) s->shading().setFixedBias(1.0f);
    const auto expected = one.render(kSize, panCamera(0));
    const auto image = n.render(kSize, panCamera(0));
    expectSameImage(expected, image, "frame " + std::to_string(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    if (frame == 2) {
      EXPECT_FLOAT_EQ(s.bias, 1.0f);
      EXPECT_GT(s.counters.chunksShaded, 0u) << "the coarser level is filled";
    }
    if (frame == 3) { EXPECT_EQ(s.counters.chunksShaded, 0u); }
  }
}

// A resize changes the output and the shade storage (it follows the output):
// nothing from before is reused, everything is shaded in that frame.
TEST(ShadeRateInvalidation, ResizeReusesNothing) {
  const auto scene = scene::makeDefaultScene(64);
  plugins::DecoupledSettings settings = settingsAt(8);
  settings.storageChunks = 0;  // storage from the output size
  settings.storageFactor = 8.0;
  Session one(scene, scene::ShadingMode::Decoupled, {.storageFactor = 8.0, .fixedBias = 0.0f});
  Session n(scene, scene::ShadingMode::Decoupled, settings);
  for (int frame = 0; frame < 4; ++frame) {
    const uint32_t size = frame < 2 ? kSize : kSize + 32;
    const auto expected = one.render(size, panCamera(0));
    const auto image = n.render(size, panCamera(0));
    expectSameImage(expected, image, "frame " + std::to_string(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    if (frame == 1) { EXPECT_GT(s.counters.chunksReused, 0u); }
    if (frame == 2) {
      EXPECT_EQ(s.counters.chunksReused, 0u) << "the resize frame";
      EXPECT_EQ(s.counters.chunksShaded, s.counters.chunksAllocated);
    }
    if (frame == 3) { EXPECT_EQ(s.counters.chunksReused, s.counters.chunksAllocated); }
  }
}


// `change` applied to both sessions before frame 2 (rate 8: a fill frame):
// that frame shows exactly what rate 1 shows, so the changed object's stored
// shading was not reused, while the other objects' was.
template <class Change>
void expectChangeReshades(const char* what, Change change) {
  const auto scene = scene::makeDefaultScene(64);
  Session one(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(8));
  for (int frame = 0; frame < 4; ++frame) {
    if (frame == 2)
      for (Session* s : {&one, &n}) change(*s);
    const auto expected = one.render(kSize, panCamera(0));
    const auto image = n.render(kSize, panCamera(0));
    expectSameImage(expected, image, std::string(what) + ", frame " + std::to_string(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << what << ", frame " << frame;
    if (frame == 2) {
      EXPECT_GT(s.counters.chunksShaded, 0u) << what << ": the changed object is reshaded";
      EXPECT_GT(s.counters.chunksReused, 0u) << what << ": the others are not";
    }
    if (frame == 3) { EXPECT_EQ(s.counters.chunksShaded, 0u) << what << ": stored again"; }
  }
}

// The gold sphere moves a little: most of its chunks stay marked, but their
// lighting changed; without invalidation they would be reused, stale.
TEST(ShadeRateInvalidation, ObjectTransformChangeReshadesIt) {
  expectChangeReshades("transform", [](Session& s) {
    const uint32_t sphere = instanceNamed(s.scene(), "gold sphere");
    const glm::mat4 world = s.scene().instances[sphere].world;
    s.renderer().setObjectTransform(sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.05f, 0.0f, 0.0f)) * world);
  });
}

// The torus gets another material (layer stack): its stored shading is of the old one.
TEST(ShadeRateInvalidation, MaterialChangeReshadesIt) {
  expectChangeReshades("material", [](Session& s) {
    s.renderer().setObjectMaterial(instanceNamed(s.scene(), "torus"), "debug-uv-checker");
  });
}

}  // namespace
}  // namespace sg::test
