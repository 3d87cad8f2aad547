// Physical exposure, validation on (docs/stability.md, "Exposure in physical
// units"): a 100,000-lux sun and an emissive of 1e4 nits
// (KHR_materials_emissive_strength) leave no Inf/NaN in the HDR colour and are
// metered to a sunny-day EV100; an unlit object keeps its base colour as its
// radiance in both paths; automatic exposure approaches its metering without
// overshooting; manual exposure is exactly 1 / (1.2 * 2^EV100).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <nlohmann/json.hpp>

#include <shadelgraph/graph/plan_dump.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;
constexpr glm::vec3 kUnlitColor{0.5f, 0.25f, 0.125f};

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

// A grey ground, a glossy sphere (a sharp sun highlight), a box glowing at 1e4
// nits and an unlit box, under a 100,000-lux sun.
scene::Scene sunlitStudio() {
  scene::Scene s;
  const int ground = addMaterial(s, {.name = "ground", .baseColorFactor = glm::vec4(0.4f, 0.4f, 0.4f, 1.0f),
                                     .metallicFactor = 0.0f, .roughnessFactor = 0.8f});
  const int glossy = addMaterial(s, {.name = "glossy", .baseColorFactor = {0.9f, 0.9f, 0.9f, 1.0f},
                                     .metallicFactor = 1.0f, .roughnessFactor = 0.05f});
  const int glow = addMaterial(s, {.name = "glow", .baseColorFactor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f),
                                   .metallicFactor = 0.0f, .emissiveFactor = {1.0f, 0.8f, 0.6f},
                                   .emissiveStrength = 1e4f});
  const int unlit = addMaterial(s, {.name = "sign", .baseColorFactor = glm::vec4(kUnlitColor, 1.0f),
                                    .metallicFactor = 0.0f, .unlit = true});
  // Split 160 a side: an untextured mesh's shadels follow its triangles (about 8 cm here, a pixel of the wide view).
  placeMesh(s, scene::makePlane(40.0f, 40.0f, 160), ground, glm::mat4(1.0f));
  placeMesh(s, scene::makeSphere(0.7f, 32, 16), glossy, at(0.0f, 0.7f, 0.0f));
  placeMesh(s, scene::makeBox({0.6f, 0.6f, 0.6f}), glow, at(1.6f, 0.3f, 0.4f));
  placeMesh(s, scene::makeBox({0.8f, 0.8f, 0.8f}), unlit, at(-1.6f, 0.4f, 0.4f));
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 1e5f,
                      .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.5f))});
  return s;
}

// Looking down: only the scene in view (the analytic sky, ambient term and
// background, follows the sun in cd/m^2, but is no surface to meter).
const scene::Camera kWide = cameraAt({0.0f, 4.0f, 3.5f}, {0.0f, 0.0f, 0.0f});
// Filled by the glowing box.
const scene::Camera kAtTheGlow = cameraAt({1.6f, 0.4f, 1.2f}, {1.6f, 0.3f, 0.4f});
// Filled by the unlit sign (0.29 cd/m^2): metered some 14 EV below the sunlit wide view.
const scene::Camera kAtTheSign = cameraAt({-1.6f, 0.4f, 1.3f}, {-1.6f, 0.4f, 0.4f});

// Pixels whose HDR colour is the unlit base colour (lit surfaces here are thousands of times brighter).
size_t unlitPixels(const std::vector<glm::vec4>& hdr) {
  size_t n = 0;
  for (const glm::vec4& p : hdr)
    if (glm::all(glm::lessThan(glm::abs(glm::vec3(p) - kUnlitColor), glm::vec3(2e-3f)))) ++n;  // half-float rounding
  return n;
}

TEST(PhysicalExposure, SunOf100000LuxAndEmissive1e4StayFiniteAndAreMetered) {
  const BothPaths both = renderBothPaths(sunlitStudio(), kSize, kSize, kWide);
  for (const auto* frame : {&both.forward, &both.decoupled}) {
    const std::string what = frame == &both.forward ? "100,000 lux forward" : "100,000 lux decoupled";
    saveForInspection(*frame, frame == &both.forward ? "exposure_sun_forward" : "exposure_sun_decoupled");
    expectFinite(*frame, what);
    const HdrSummary s = summarize(frame->hdr);
    const shader::SgExposure& e = frame->exposure;
    std::printf("%s: HDR max %.0f, EV100 %.2f, exposure %.3g (host %.3g), mean %.1f/255, unlit pixels %zu\n",
                what.c_str(), double(s.maxValue), double(e.ev100), double(e.exposure), s.exposure,
                meanLevel(frame->ldr), unlitPixels(frame->hdr));
    // The pass ran on this image: its exposure is the host's evaluation of its formula.
    EXPECT_NEAR(double(e.exposure) / s.exposure, 1.0, 1e-3) << what;
    EXPECT_FLOAT_EQ(e.exposure, 1.0f / (1.2f * std::exp2(e.ev100))) << what;
    // A sunny-day exposure (sunny 16: EV100 15), not the old clamp's gain of 0.1 (EV100 3.1).
    EXPECT_GT(e.ev100, 12.0f) << what;
    EXPECT_LT(e.ev100, 19.0f) << what;
    // Neither black nor blown out.
    EXPECT_GT(meanLevel(frame->ldr), 30.0) << what;
    EXPECT_LT(meanLevel(frame->ldr), 200.0) << what;
    // KHR_materials_unlit: the base colour is the radiance, in both paths (a 64-pixel face at least).
    EXPECT_GE(unlitPixels(frame->hdr), 64u) << what;
  }
  expectClean(both.decoupled, "100,000 lux decoupled");
  expectAgreement(both.decoupled, both.forward, {}, "100,000 lux: decoupled vs forward");
}

// Frames 1.. after a cut from a view metered far brighter (the sunlit wide
// view to the unlit sign filling the frame): the EV100 moves to the new
// metering monotonically, each frame closing `adaptation` of the gap.
TEST(PhysicalExposure, AutoExposureSettlesWithoutOscillating) {
  for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) {
    const char* what = mode == scene::ShadingMode::Forward ? "forward" : "decoupled";
    StabilitySession session(sunlitStudio(), mode, {}, {{"adaptation", 0.4}});
    const StabilityFrame glare = session.render(kSize, kWide);
    EXPECT_EQ(glare.exposure.ev100, glare.exposure.targetEv100) << what << ": the first frame has no history";
    std::vector<float> ev, target;
    for (int i = 0; i < 16; ++i) {
      const StabilityFrame f = session.render(kSize, kAtTheSign);
      expectFinite(f, what);
      ev.push_back(f.exposure.ev100);
      target.push_back(f.exposure.targetEv100);
    }
    std::printf("%s: metered %.2f wide, %.2f at the sign; EV100 after the cut:", what, double(glare.exposure.ev100),
                double(target[0]));
    for (float v : ev) std::printf(" %.2f", double(v));
    std::printf("\n");
    ASSERT_GT(glare.exposure.ev100 - target[0], 1.0f) << what << ": the cut must change the metering";
    for (size_t i = 0; i < ev.size(); ++i) {
      EXPECT_NEAR(target[i], target[0], 1e-3f) << what << ": a still view meters the same every frame";
      const float before = i == 0 ? glare.exposure.ev100 : ev[i - 1];
      // Never past the metering (no overshoot), never away from it, by the stated fraction of the gap.
      EXPECT_GE(ev[i], target[i] - 1e-4f) << what << " frame " << i;
      EXPECT_LE(ev[i], before + 1e-4f) << what << " frame " << i;
      EXPECT_NEAR(ev[i] - target[i], 0.6f * (before - target[i]), 1e-3f) << what << " frame " << i;
    }
    EXPECT_NEAR(ev.back(), target.back(), 0.01f) << what << ": settled";
  }
}

// The same hard case with bloom, which the 1e4 emission calls for (at least
// 10 cd/m^2, passes/bloom): the HDR colour tonemap reads, after bloom, has no
// Inf/NaN in any frame, and auto exposure still settles after a cut without
// oscillating (bloom runs after the metering, so it cannot feed back into it).
TEST(PhysicalExposure, WithBloomStaysFiniteAndSettles) {
  for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) {
    const char* what = mode == scene::ShadingMode::Forward ? "forward, bloom" : "decoupled, bloom";
    StabilitySession session(sunlitStudio(), mode, {}, {{"adaptation", 0.4}}, kHdrFinalCapturedFrame);
    const auto plan = nlohmann::json::parse(graph::toJson(session.plan(kSize, kSize, kAtTheGlow)));
    bool bloom = false;
    for (const auto& p : plan["passes"]) bloom |= p["name"] == "bloom" && !p["culled"].get<bool>();
    ASSERT_TRUE(bloom) << what << ": the 1e4 emission calls for bloom";
    const StabilityFrame glare = session.render(kSize, kAtTheGlow);
    expectFinite(glare, what);
    float before = glare.exposure.ev100, maxValue = summarize(glare.hdr).maxValue;
    for (int i = 0; i < 12; ++i) {
      const StabilityFrame f = session.render(kSize, kWide);
      expectFinite(f, what);
      maxValue = std::max(maxValue, summarize(f.hdr).maxValue);
      EXPECT_GE(f.exposure.ev100, f.exposure.targetEv100 - 1e-4f) << what << " frame " << i << ": overshoot";
      EXPECT_LE(f.exposure.ev100, before + 1e-4f) << what << " frame " << i << ": moved away from the metering";
      before = f.exposure.ev100;
      if (i == 11) {
        EXPECT_NEAR(f.exposure.ev100, f.exposure.targetEv100, 0.05f) << what << ": settled";
      }
    }
    std::printf("%s: EV100 %.2f at the glow, %.2f after 12 frames wide; HDR max after bloom %.0f\n", what,
                double(glare.exposure.ev100), double(before), double(maxValue));
  }
}

TEST(PhysicalExposure, ManualExposureIsTheSensorModel) {
  StabilitySession session(sunlitStudio(), scene::ShadingMode::Forward, {}, {{"mode", "manual"}, {"ev100", 15.0}});
  const StabilityFrame f = session.render(kSize, kWide);
  saveForInspection(f, "exposure_manual_ev15");
  EXPECT_EQ(f.exposure.ev100, 15.0f);
  EXPECT_FLOAT_EQ(f.exposure.exposure, 1.0f / (1.2f * 32768.0f));
  // Sunny 16 on a 100,000-lux day: an 18% grey would read about middle grey; the image is not black.
  EXPECT_GT(meanLevel(f.ldr), 30.0);
}

}  // namespace
}  // namespace sg::test
