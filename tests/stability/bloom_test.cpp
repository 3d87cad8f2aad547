// Bloom (passes/bloom): present only when a visible object emits at least the
// threshold (the effect matrix checks presence); when present it adds the
// light above white around bright pixels and takes nothing away.
#include <gtest/gtest.h>

#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

// A dark ground and a small box emitting 1000 cd/m^2 under a 3-lux sun: at
// EV100 0 (manual) the box is 800 times white.
scene::Scene glowInTheDark() {
  scene::Scene s;
  const int ground = addMaterial(s, {.name = "ground", .baseColorFactor = glm::vec4(0.3f), .metallicFactor = 0.0f});
  const int glow = addMaterial(s, {.name = "glow", .baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f),
                                   .metallicFactor = 0.0f, .emissiveFactor = {1.0f, 0.6f, 0.3f},
                                   .emissiveStrength = 1000.0f});
  placeMesh(s, scene::makePlane(8.0f, 8.0f, 4), ground, glm::mat4(1.0f));
  placeMesh(s, scene::makeBox({0.3f, 0.3f, 0.3f}), glow, glm::translate(glm::mat4(1.0f), {0.0f, 0.15f, 0.0f}));
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
                      .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f))});
  return s;
}

TEST(Bloom, AddsAHaloAroundLightAboveWhiteAndTakesNothingAway) {
  const auto camera = cameraAt({0.0f, 1.5f, 3.0f}, {0.0f, 0.15f, 0.0f});
  const nlohmann::json manual = {{"mode", "manual"}, {"ev100", 0.0}};
  for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) {
    const char* what = mode == scene::ShadingMode::Forward ? "forward" : "decoupled";
    StabilitySession plain(glowInTheDark(), mode, {}, manual, kHdrCapturedFrame);       // before bloom
    StabilitySession bloomed(glowInTheDark(), mode, {}, manual, kHdrFinalCapturedFrame);  // after it
    const StabilityFrame a = plain.render(96, 64, camera), b = bloomed.render(96, 64, camera);
    saveForInspection(b, std::string("bloom_") + what);
    expectFinite(b, what);
    ASSERT_EQ(a.hdr.size(), b.hdr.size());
    size_t brighter = 0, darker = 0, haloOnDark = 0;
    for (size_t i = 0; i < a.hdr.size(); ++i) {
      const float before = a.hdr[i].g, after = b.hdr[i].g;
      if (after > before * 1.01f + 1e-3f) ++brighter;
      if (after < before * 0.99f - 1e-3f) ++darker;
      if (before < 0.5f && after > before + 0.05f) ++haloOnDark;  // a ground pixel (below white) lit by the halo
    }
    std::printf("%s: %zu of %zu pixels brighter after bloom, %zu darker, %zu dark ones in the halo\n", what, brighter,
                a.hdr.size(), darker, haloOnDark);
    EXPECT_EQ(darker, 0u) << what << ": bloom only adds light (half-float rounding aside)";
    EXPECT_GT(haloOnDark, 20u) << what << ": a halo spreads onto the dark ground around the glow";
  }
}

}  // namespace
}  // namespace sg::test
