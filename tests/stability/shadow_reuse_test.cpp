// Decoupled shading keeps a shadel's shadow term with the rest of its stored
// shading (issue 16: "reuse it while light and casters stay still"): the term
// is computed per shadel inside the material's light loop (lights.glsl, not a
// layer) and kept between shade frames (--shade-rate) like everything else a
// shadel holds. Here a caster moves between shade frames: the ground its
// shadow falls on is reshaded although the ground did not move (render::
// shadowMayFallOn), an object out of the shadow's way keeps its shading, and
// the image is exactly that of shading every frame.
#include <gtest/gtest.h>

#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

// A ground, a crate casting the sun's shadow on it, and a sphere up-sun of the crate (never in its shadow).
scene::Scene crateInTheSun() {
  scene::Scene s;
  const int grey = addMaterial(s, {.name = "grey", .baseColorFactor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f),
                                   .metallicFactor = 0.0f, .roughnessFactor = 0.9f});
  placeMesh(s, scene::makePlane(8.0f, 8.0f, 48), grey, glm::mat4(1.0f));
  placeMesh(s, scene::makeBox({1.0f, 1.0f, 1.0f}), grey, at(0.0f, 0.5f, 0.0f));
  placeMesh(s, scene::makeSphere(0.5f, 32, 16), grey, at(-2.5f, 0.5f, -2.5f));
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
                      .direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.6f))});
  return s;
}

constexpr uint32_t kCrate = 1;

TEST(ShadowReuse, AMovedCasterReshadesTheObjectsItsShadowMayFallOnAndNoOthers) {
  const scene::Scene s = crateInTheSun();
  ASSERT_TRUE(s.lights[0].shadows) << "the sun is shadowed";
  const scene::Camera camera = cameraAt({1.5f, 4.0f, 6.0f}, {0.0f, 0.3f, 0.0f});
  // Ample storage and a fixed bias: these compare reuse, not the adjuster.
  const auto settingsAt = [](uint32_t rate) {
    return plugins::DecoupledSettings{.storageChunks = 8192, .fixedBias = 0.0f, .shadeRate = rate};
  };
  StabilitySession everyFrame(s, scene::ShadingMode::Decoupled, settingsAt(1));
  StabilitySession kept(s, scene::ShadingMode::Decoupled, settingsAt(8));
  for (int frame = 0; frame < 4; ++frame) {
    if (frame == 2)
      for (StabilitySession* session : {&everyFrame, &kept})
        session->renderer().setObjectTransform(kCrate, at(0.4f, 0.5f, 0.3f));
    const StabilityFrame expected = everyFrame.render(kSize, camera);
    const StabilityFrame f = kept.render(kSize, camera);
    const std::string what = "frame " + std::to_string(frame);
    expectClean(f, what);
    const auto d = image::compareRgba8(expected.ldr.rgba8, f.ldr.rgba8);
    EXPECT_EQ(d.maxAbs, 0) << what << ": differs from shading every frame (PSNR " << d.psnr << " dB)";
    const auto& c = f.stats.counters;
    std::printf("%s: %u chunks shaded, %u reused\n", what.c_str(), unsigned(c.chunksShaded), unsigned(c.chunksReused));
    if (frame == 1) {
      EXPECT_EQ(c.chunksShaded, 0u) << "nothing moved: every shadel keeps its shadow";
      EXPECT_GT(c.chunksReused, 0u);
    }
    if (frame == 2) {
      EXPECT_GT(c.chunksShaded, 0u) << "the crate and the ground under its shadow are reshaded";
      EXPECT_GT(c.chunksReused, 0u) << "the sphere up-sun keeps its shading";
    }
    if (frame == 3) { EXPECT_EQ(c.chunksShaded, 0u) << "still again: kept"; }
  }
}

}  // namespace
}  // namespace sg::test
