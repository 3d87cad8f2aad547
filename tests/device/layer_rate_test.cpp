// Per-layer shade rate on the device (validation on): a view-independent
// layer keeps its values across shade frames while only the camera moves,
// is recomputed where its inputs change (its object moves, for a layer that
// depends on the world pose) and every refreshShadeFrames-th shade frame,
// and keeping it changes no pixel.
#include <gtest/gtest.h>

#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;

plugins::DecoupledSettings settingsAt(uint32_t rate) {
  return {.storageChunks = 8192, .fixedBias = 0.0f, .shadeRate = rate};
}



// The default scene with every object in `material`, or only `only` when given.
scene::Scene sceneWith(const std::string& material, const std::string& only = "") {
  auto s = scene::makeDefaultScene(64);
  for (auto& instance : s.instances)
    if (only.empty() || instance.name == only) instance.material = material;
  return s;
}

plugins::LayerReuse layerReuse(const plugins::DecoupledStats& s, const std::string& layer) {
  for (const auto& reuse : s.layerReuse)
    if (reuse.layer == layer) return reuse;
  ADD_FAILURE() << "layer '" << layer << "' has no reuse counters this frame";
  return {};
}

void expectSameImage(const gpu::HostImage& expected, const gpu::HostImage& actual, const std::string& what) {
  const auto diff = image::compareRgba8(expected.rgba8, actual.rgba8);
  EXPECT_EQ(diff.maxAbs, 0) << what << ": PSNR " << diff.psnr << " dB";
}

// Every frame a shade frame (rate 1), a static camera: after the first frame
// the diffuse layer is served entirely from the frame before, until its
// refresh frame (the 8th shade frame) recomputes all of it; the image is the
// same as with the layer computed every frame.
TEST(LayerRate, ViewIndependentLayerIsKeptAcrossShadeFramesAndRefreshed) {
  const auto scene = sceneWith("split-pbr");
  Session kept(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  auto computedSettings = settingsAt(1);
  computedSettings.keepViewIndependentLayers = false;
  Session computed(scene, scene::ShadingMode::Decoupled, computedSettings);
  for (int frame = 1; frame <= 9; ++frame) {
    const auto image = kept.render(kSize, panCamera(0));
    expectSameImage(computed.render(kSize, panCamera(0)), image, "frame " + std::to_string(frame));
    const auto s = kept.stats();
    EXPECT_TRUE(s.shadeFrame);
    EXPECT_EQ(s.counters.compositeMisses, 0u);
    const auto diffuse = layerReuse(s, "diffuse-light");
    const bool recompute = frame == 1 || frame == 8;  // nothing stored yet; the refresh
    if (recompute) {
      EXPECT_EQ(diffuse.reused, 0u) << "frame " << frame;
      EXPECT_GT(diffuse.computed, 0u) << "frame " << frame;
    } else {
      EXPECT_GT(diffuse.reused, 0u) << "frame " << frame;
      EXPECT_EQ(diffuse.computed, 0u) << "frame " << frame << ": only the camera could have changed, and did not";
    }
    EXPECT_EQ(layerReuse(computed.stats(), "diffuse-light").reused, 0u) << "keeping switched off";
  }
}

// A panning camera at rate 2: on each shade frame the specular layer is
// recomputed everywhere, the diffuse layer only where the pan uncovered
// shadels that were not stored the frame before.
TEST(LayerRate, ViewIndependentLayerIsNotReshadedWhenOnlyTheCameraMoves) {
  Session n(sceneWith("split-pbr"), scene::ShadingMode::Decoupled, settingsAt(2));
  for (int frame = 0; frame < 7; ++frame) {
    n.render(kSize, panCamera(frame));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u) << "frame " << frame;
    if (frame == 0 || !s.shadeFrame) continue;
    const auto diffuse = layerReuse(s, "diffuse-light");
    EXPECT_GT(diffuse.reused, 0u) << "frame " << frame;
    EXPECT_LT(diffuse.computed, diffuse.reused / 4) << "frame " << frame << ": mostly kept";
    EXPECT_EQ(s.counters.chunksShaded, s.counters.chunksAllocated) << "a shade frame shades every chunk";
    EXPECT_LE(diffuse.reused + diffuse.computed, uint64_t(s.counters.chunksShaded) * 64) << "frame " << frame;
  }
}

// Its inputs change: the gold sphere moves between two shade frames. Its
// diffuse layer (depends on the world pose) is recomputed, the other objects'
// kept; the image is that of the layer computed every frame.
TEST(LayerRate, WorldLayerIsReshadedWhenItsObjectMoves) {
  const auto scene = sceneWith("split-pbr");
  Session kept(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  auto computedSettings = settingsAt(1);
  computedSettings.keepViewIndependentLayers = false;
  Session computed(scene, scene::ShadingMode::Decoupled, computedSettings);
  const uint32_t sphere = instanceNamed(scene, "gold sphere");
  uint64_t keptBefore = 0;
  for (int frame = 0; frame < 4; ++frame) {
    if (frame == 2)
      for (Session* s : {&kept, &computed})
        s->renderer().setObjectTransform(
            sphere, glm::translate(glm::mat4(1.0f), glm::vec3(0.05f, 0.0f, 0.0f)) * scene.instances[sphere].world);
    const auto image = kept.render(kSize, panCamera(0));
    expectSameImage(computed.render(kSize, panCamera(0)), image, "frame " + std::to_string(frame));
    const auto diffuse = layerReuse(kept.stats(), "diffuse-light");
    if (frame == 1) {
      EXPECT_EQ(diffuse.computed, 0u);
      keptBefore = diffuse.reused;
    }
    if (frame == 2) {
      EXPECT_GT(diffuse.computed, 0u) << "the moved sphere's diffuse light is recomputed";
      EXPECT_GT(diffuse.reused, 0u) << "the others' is kept";
      EXPECT_LT(diffuse.reused, keptBefore);
    }
    if (frame == 3) { EXPECT_EQ(diffuse.computed, 0u) << "nothing moved since"; }
  }
}

// A layer that depends only on the surface (the bumps material's height, a
// function of the texture coordinate) is kept even while its object moves.
TEST(LayerRate, SurfaceLayerIsKeptWhileItsObjectMovesRigidly) {
  const auto scene = sceneWith("bumps", "gold sphere");
  Session n(scene, scene::ShadingMode::Decoupled, settingsAt(1));
  const uint32_t sphere = instanceNamed(scene, "gold sphere");
  for (int frame = 0; frame < 4; ++frame) {
    // A tiny move each frame: the sphere's marked chunks stay (nearly) the same.
    n.renderer().setObjectTransform(
        sphere, glm::translate(glm::mat4(1.0f), glm::vec3(1e-4f * float(frame), 0.0f, 0.0f)) *
                    scene.instances[sphere].world);
    n.render(kSize, panCamera(0));
    const auto s = n.stats();
    EXPECT_EQ(s.counters.compositeMisses, 0u);
    if (frame == 0) continue;
    const auto height = layerReuse(s, "height");
    EXPECT_GT(height.reused, 0u) << "frame " << frame;
    EXPECT_LT(height.computed * 10, height.reused) << "frame " << frame << ": at most a border recomputed";
  }
}

// Another material invalidates what the object's kept layers stored.
TEST(LayerRate, MaterialChangeRecomputesKeptLayers) {
  Session n(sceneWith("split-pbr"), scene::ShadingMode::Decoupled, settingsAt(1));
  const uint32_t torus = instanceNamed(n.scene(), "torus");
  for (int frame = 0; frame < 3; ++frame) {
    if (frame == 2) n.renderer().setObjectMaterial(torus, "gltf-pbr");
    n.render(kSize, panCamera(0));
  }
  // Back to split-pbr: the torus' diffuse values in the history are of frame 1, not of its material now.
  n.renderer().setObjectMaterial(torus, "split-pbr");
  n.render(kSize, panCamera(0));
  const auto diffuse = layerReuse(n.stats(), "diffuse-light");
  EXPECT_GT(diffuse.computed, 0u) << "the torus is recomputed";
  EXPECT_GT(diffuse.reused, 0u) << "the others are kept";
  EXPECT_EQ(n.stats().counters.compositeMisses, 0u);
}

}  // namespace
}  // namespace sg::test
