// Environment light (issue 16, "Environment light"): a scene naming an
// equirectangular HDR image is lit by it (image-based lighting from the
// one-time prefilter), the same in the forward fragment variant and the
// decoupled compute variant of a material (gltf-pbr, split-pbr), and the
// sample asset EnvironmentTest renders under it. The test image is the
// procedural sky of benchmarks/environment/procedural_sky.hpp (no HDR environment ships
// with the sample assets or Debian).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/render/frame_uniforms.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "procedural_sky.hpp"
#include "stability_checks.hpp"
#include "stability_scenes.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

scene::Environment proceduralSky(float intensity) {
  TempDir dir;
  bench::writeProceduralSky(dir.path() / "sky.hdr");
  return scene::loadEnvironment(dir.path() / "sky.hdr", intensity);
}

// A ground, a rough white sphere, a glossy metal sphere and a rough copper one, lit by
// the sky image (1000 cd/m^2 a unit) and a 3000-lux sun.
scene::Scene skyLitSpheres(const std::string& material) {
  scene::Scene s;
  const int ground = addMaterial(s, {.name = "ground", .baseColorFactor = glm::vec4(0.5f), .metallicFactor = 0.0f,
                                     .roughnessFactor = 0.9f});
  const int white = addMaterial(s, {.name = "white", .baseColorFactor = glm::vec4(0.9f), .metallicFactor = 0.0f,
                                    .roughnessFactor = 0.7f});
  const int chrome = addMaterial(s, {.name = "chrome", .baseColorFactor = glm::vec4(0.95f), .metallicFactor = 1.0f,
                                     .roughnessFactor = 0.15f});
  const int copper = addMaterial(s, {.name = "copper", .baseColorFactor = {0.95f, 0.64f, 0.54f, 1.0f},
                                     .metallicFactor = 1.0f, .roughnessFactor = 0.5f});
  // Split 64 a side: an untextured mesh's shadels follow its triangles (3 cm here, so the shadows are as sharp as forward's).
  placeMesh(s, scene::makePlane(8.0f, 8.0f, 64), ground, glm::mat4(1.0f));
  placeMesh(s, scene::makeSphere(0.6f, 48, 24), white, at(-1.4f, 0.6f, 0.0f));
  placeMesh(s, scene::makeSphere(0.6f, 48, 24), chrome, at(0.0f, 0.6f, 0.0f));
  placeMesh(s, scene::makeSphere(0.6f, 48, 24), copper, at(1.4f, 0.6f, 0.0f));
  for (auto& instance : s.instances) instance.material = material;
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3000.0f,
                      .direction = glm::normalize(glm::vec3(-0.7f, -0.84f, 0.7f))});
  s.environment = proceduralSky(1000.0f);
  return s;
}

// RoughLevelsHaveNoStreaks measured 0.107 forward / 0.082 decoupled with unfiltered
// sampling (128 samples of level 0), 0.005 / 0.004 with filtered importance sampling.
constexpr double kStreakBound = 0.02;

const scene::Camera kView = cameraAt({0.0f, 1.6f, 4.2f}, {0.0f, 0.5f, 0.0f});

class EnvironmentLight : public ::testing::TestWithParam<const char*> {};

// One source, two variants: the decoupled render agrees with the forward one
// as the other agreement tests require (30 dB, mean 2/255), and the image
// actually lights the scene (it differs from the analytic sky's render).
TEST_P(EnvironmentLight, ForwardAndDecoupledAgree) {
  const std::string material = GetParam();
  const scene::Scene lit = skyLitSpheres(material);
  const BothPaths both = renderBothPaths(lit, 192, 108, kView);
  saveForInspection(both.forward, "environment_" + material + "_forward");
  saveForInspection(both.decoupled, "environment_" + material + "_decoupled");
  expectFinite(both.forward, material + " forward");
  expectClean(both.decoupled, material + " decoupled");
  expectAgreement(both.decoupled, both.forward, {}, material + " with IBL: decoupled vs forward");

  scene::Scene skyOnly = lit;
  skyOnly.environment = {};
  StabilitySession analytic(skyOnly, scene::ShadingMode::Forward);
  const auto without = analytic.render(192, 108, kView);
  const auto d = image::compareRgba8(without.ldr.rgba8, both.forward.ldr.rgba8);
  std::printf("%s: analytic sky vs environment image: mean |d| %.2f/255\n", material.c_str(), d.meanAbs);
  EXPECT_GT(d.meanAbs, 3.0) << "the environment image must change the lighting";
}

INSTANTIATE_TEST_SUITE_P(Materials, EnvironmentLight, ::testing::Values("gltf-pbr", "split-pbr"),
                         [](const auto& param) { return std::string(param.param) == "gltf-pbr" ? "GltfPbr" : "SplitPbr"; });

// The image's orientation reaches the shading: a white sphere under a blue sky
// over brown ground (no other light) is bluish on top and brownish below, in both paths.
TEST(EnvironmentLightOrientation, SkyAboveGroundBelow) {
  scene::Scene s;
  const int white = addMaterial(s, {.name = "white", .baseColorFactor = glm::vec4(1.0f), .metallicFactor = 0.0f,
                                    .roughnessFactor = 1.0f});
  placeMesh(s, scene::makeSphere(1.0f, 48, 24), white, glm::mat4(1.0f));
  // A light of no intensity: the scene has a light, so no default sun is added.
  s.lights.push_back({.name = "off", .type = scene::LightType::Directional, .intensity = 0.0f});
  s.environment = proceduralSky(1.0f);
  const uint32_t size = 64;
  const BothPaths both = renderBothPaths(s, size, size, cameraAt({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}));
  for (const auto* f : {&both.forward, &both.decoupled}) {
    const char* what = f == &both.forward ? "forward" : "decoupled";
    expectFinite(*f, what);
    const glm::vec4 top = f->hdr[size_t(size / 4) * size + size / 2], bottom = f->hdr[size_t(3 * size / 4) * size + size / 2];
    std::printf("%s: top (%.3f %.3f %.3f) bottom (%.3f %.3f %.3f)\n", what, double(top.r), double(top.g),
                double(top.b), double(bottom.r), double(bottom.g), double(bottom.b));
    EXPECT_GT(top.b, 1.15f * top.r) << what << ": the upper half faces the blue sky";
    // The ground is 2.0 red to blue; the rough lobe takes in sky too (1.30 unfiltered, 1.297 with filtered importance sampling).
    EXPECT_GT(bottom.r, 1.25f * bottom.b) << what << ": the lower half faces the brown ground";
    EXPECT_GT(top.g, bottom.g) << what << ": the sky is brighter than the ground";
  }
}

// A scene without lights gets the default sun, unless an environment image lights it
// (EnvironmentTest's screenshot has no sun: no sun highlight, no terminator).
TEST(EnvironmentImage, ReplacesTheDefaultSun) {
  scene::Scene s;
  placeMesh(s, scene::makeSphere(1.0f, 16, 8), addMaterial(s, {.name = "white"}), glm::mat4(1.0f));
  const scene::Camera camera = cameraAt({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f});
  std::vector<render::GpuLight> lights;
  EXPECT_EQ(render::makeFrameUniforms(s, camera, 64, 64, lights).counts.x, 1u) << "no lights, no image: the default sun";
  s.environment = proceduralSky(1.0f);
  EXPECT_EQ(render::makeFrameUniforms(s, camera, 64, 64, lights).counts.x, 0u) << "the image lights it alone";
}

// The image's bilinear radiance along d (environment.glsl's mapping: u wraps, v clamps), the reference.
glm::vec3 radianceAlong(const scene::Environment& env, glm::vec3 d) {
  const float pi = 3.14159265358979f;
  d = glm::normalize(d);
  const float u = std::atan2(d.x, -d.z) / (2.0f * pi) + 0.5f, v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / pi;
  const float tx = u * float(env.width) - 0.5f, ty = v * float(env.height) - 0.5f;
  const int bx = int(std::floor(tx)), by = int(std::floor(ty));
  const float fx = tx - float(bx), fy = ty - float(by);
  glm::vec3 c(0.0f);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int x = ((bx + i) % int(env.width) + int(env.width)) % int(env.width);
      const int y = std::clamp(by + j, 0, int(env.height) - 1);
      const float* t = &env.rgba[(size_t(y) * env.width + size_t(x)) * 4];
      c += (i == 0 ? 1.0f - fx : fx) * (j == 0 ? 1.0f - fy : fy) * glm::vec3(t[0], t[1], t[2]);
    }
  return c * env.intensity;
}

// The world-space ray through pixel (x, y) of a width x height render from `camera` (row 0 at the top).
glm::vec3 rayThrough(const scene::Camera& camera, uint32_t width, uint32_t height, uint32_t x, uint32_t y) {
  const glm::mat4 clipToWorld =
      glm::inverse(camera.projectionMatrix(float(width) / float(height)) * camera.view());
  const glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(height) * 2.0f);
  const glm::vec4 n = clipToWorld * glm::vec4(ndc, 0.0f, 1.0f), f = clipToWorld * glm::vec4(ndc, 0.5f, 1.0f);
  return glm::normalize(glm::vec3(f) / f.w - glm::vec3(n) / n.w);
}

// Whether the ray from `eye` along unit `d` passes within `radius` of `centre`.
bool passesNear(glm::vec3 eye, glm::vec3 d, glm::vec3 centre, float radius) {
  const glm::vec3 c = centre - eye;
  const float along = glm::dot(c, d);
  return along > 0.0f && glm::length(c - along * d) < radius;
}

const glm::vec3 kSkySunDirection = glm::normalize(glm::vec3(0.7f, std::tan(40.0f * 3.14159265f / 180.0f), -0.7f));

// Where nothing is drawn, the HDR colour is the environment image's radiance
// (times its intensity) in the view direction, in both paths: a camera looking
// at the procedural sky's sun over a sphere; pixels well off the sphere are
// compared with a bilinear read of the image on the CPU (within 2% of the
// value plus a tenth of what it changes by within 1 mrad), and the sun disc must
// be where the image has it.
TEST(EnvironmentBackground, IsTheImageInTheViewDirection) {
  scene::Scene s;
  const glm::vec3 eye(0.0f, 0.3f, 0.0f), centre = eye + 4.0f * kSkySunDirection + glm::vec3(0.9f, -0.4f, 0.6f);
  placeMesh(s, scene::makeSphere(0.7f, 32, 16), addMaterial(s, {.name = "grey", .metallicFactor = 0.0f}),
            glm::translate(glm::mat4(1.0f), centre));
  s.lights.push_back({.name = "off", .type = scene::LightType::Directional, .intensity = 0.0f});
  TempDir dir;
  bench::writeProceduralSky(dir.path() / "sky.hdr", 256, 128, 500.0f);
  s.environment = scene::loadEnvironment(dir.path() / "sky.hdr", 2.0f);
  const uint32_t w = 160, h = 96;
  const scene::Camera camera = cameraAt(eye, eye + kSkySunDirection);
  const BothPaths both = renderBothPaths(s, w, h, camera);
  saveForInspection(both.forward, "environment_background_forward");
  saveForInspection(both.decoupled, "environment_background_decoupled");
  uint32_t compared = 0, wrong = 0, disagree = 0;
  float worst = 0.0f, brightest = 0.0f;
  glm::vec3 brightestRay(0.0f);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const glm::vec3 d = rayThrough(camera, w, h, x, y);
      if (passesNear(eye, d, centre, 0.7f + 0.08f)) continue;  // the sphere and a margin round its silhouette
      const glm::vec3 expected = radianceAlong(s.environment, d);
      // What the image changes by within 1 mrad (1/25 texel) of d: GPU and CPU trigonometry
      // differ by a fraction of that, which matters only on the sun disc's edge.
      glm::vec3 lo = expected, hi = expected;
      for (const glm::vec3 e : {glm::vec3(1e-3f, 0, 0), glm::vec3(-1e-3f, 0, 0), glm::vec3(0, 1e-3f, 0),
                                glm::vec3(0, -1e-3f, 0), glm::vec3(0, 0, 1e-3f), glm::vec3(0, 0, -1e-3f)}) {
        const glm::vec3 r = radianceAlong(s.environment, d + e);
        lo = glm::min(lo, r), hi = glm::max(hi, r);
      }
      const glm::vec3 fwd = glm::vec3(both.forward.hdr[size_t(y) * w + x]);
      const glm::vec3 dec = glm::vec3(both.decoupled.hdr[size_t(y) * w + x]);
      ++compared;
      for (int k = 0; k < 3; ++k) {
        // Allowed: 2% of the value, and 1/10 of the change within 1 mrad (0.1 mrad of direction).
        const float error = std::abs(fwd[k] - expected[k]) / (0.02f * (expected[k] + 0.01f) + 0.1f * (hi[k] - lo[k]));
        worst = std::max(worst, error);
        if (error > 1.0f && wrong++ < 3)
          std::printf("  pixel (%u, %u) channel %d: %.4f, the image %.4f\n", x, y, k, double(fwd[k]), double(expected[k]));
        if (std::abs(dec[k] - fwd[k]) > 1e-3f * (fwd[k] + 1.0f)) ++disagree;
      }
      if (fwd.g > brightest) brightest = fwd.g, brightestRay = d;
    }
  const float sunOff = glm::degrees(std::acos(std::min(glm::dot(brightestRay, kSkySunDirection), 1.0f)));
  std::printf("background: %u pixels compared, worst error %.3f of the allowed, %u channels beyond it, %u forward/decoupled "
              "disagreements; brightest %.1f at %.2f deg from the sun\n",
              compared, double(worst), wrong, disagree, double(brightest), double(sunOff));
  EXPECT_GT(compared, w * h / 2) << "most of the view is background";
  EXPECT_EQ(wrong, 0u) << "background channels off the image's radiance";
  EXPECT_EQ(disagree, 0u) << "forward and decoupled backgrounds differ";
  EXPECT_NEAR(brightest, 1000.0f, 10.0f) << "the sun disc (500 x intensity 2) is in view";
  EXPECT_LT(sunOff, 5.0f) << "the sun disc (5 degrees in radius) is where the image has it";
}

// Without an image the background stays the clear colour: flat.
TEST(EnvironmentBackground, WithoutAnImageTheBackgroundIsFlat) {
  scene::Scene s;
  placeMesh(s, scene::makeSphere(0.5f, 16, 8), addMaterial(s, {.name = "grey"}), glm::mat4(1.0f));
  StabilitySession session(s, scene::ShadingMode::Forward);
  const auto f = session.render(64, 48, cameraAt({0.0f, 0.0f, 4.0f}, {0.0f, 0.0f, 0.0f}));
  EXPECT_EQ(f.hdr.front(), f.hdr.back()) << "top-left and bottom-right corners: the clear colour";
}

// A rough prefiltered level holds no streaks: a metal sphere of roughness 0.8
// (level 4 of 6) filling the view under the procedural sky's sun (500 times
// the sky: the bright spot too few unfiltered samples alias into streaks) has
// a smooth reflection. Measured as the mean relative Laplacian of the
// luminance over the sphere's inside (a smooth lobe varies slowly pixel to pixel).
TEST(EnvironmentPrefilter, RoughLevelsHaveNoStreaks) {
  scene::Scene s;
  placeMesh(s, scene::makeSphere(1.0f, 96, 48),
            addMaterial(s, {.name = "rough metal", .baseColorFactor = glm::vec4(0.9f), .metallicFactor = 1.0f,
                            .roughnessFactor = 0.8f}),
            glm::mat4(1.0f));
  s.lights.push_back({.name = "off", .type = scene::LightType::Directional, .intensity = 0.0f});
  s.environment = proceduralSky(1.0f);
  const uint32_t size = 160;
  const glm::vec3 eye(0.0f, 0.0f, 2.6f);
  const scene::Camera camera = cameraAt(eye, {0.0f, 0.0f, 0.0f});
  const BothPaths both = renderBothPaths(s, size, size, camera);
  saveForInspection(both.forward, "environment_rough_metal_forward");
  saveForInspection(both.decoupled, "environment_rough_metal_decoupled");
  for (const auto* f : {&both.forward, &both.decoupled}) {
    const char* what = f == &both.forward ? "forward" : "decoupled";
    const auto luminance = [&](uint32_t x, uint32_t y) {
      return glm::dot(glm::vec3(f->hdr[size_t(y) * size + x]), glm::vec3(0.2126f, 0.7152f, 0.0722f));
    };
    double sum = 0.0;
    uint32_t n = 0;
    for (uint32_t y = 1; y + 1 < size; ++y)
      for (uint32_t x = 1; x + 1 < size; ++x) {
        // Inside the sphere, away from its silhouette (its ray passes within 0.85 of the centre).
        if (!passesNear(eye, rayThrough(camera, size, size, x, y), glm::vec3(0.0f), 0.85f)) continue;
        const float l = luminance(x, y);
        const float lap = 4.0f * l - luminance(x - 1, y) - luminance(x + 1, y) - luminance(x, y - 1) - luminance(x, y + 1);
        sum += double(std::abs(lap) / std::max(l, 1e-3f));
        ++n;
      }
    const double mean = sum / std::max(n, 1u);
    std::printf("%s: rough metal sphere, %u pixels, mean relative Laplacian %.5f\n", what, n, mean);
    ASSERT_GT(n, size * size / 4) << what;
    EXPECT_LT(mean, kStreakBound) << what << ": streaks in the rough reflection";
  }
}

// The sample asset meant for environment light: its metal/rough grid under the
// procedural sky, both paths; the picture is written for a look (SG_TEST_IMAGES).
TEST(EnvironmentLightAsset, EnvironmentTestRenders) {
  SG_REQUIRE_ASSETS();
  scene::Scene s = scene::loadGltf(samplePath("EnvironmentTest"));
  s.environment = proceduralSky(1.0f);
  const BothPaths both = renderBothPaths(s, 320, 180);
  saveForInspection(both.forward, "environment_test_forward");
  saveForInspection(both.decoupled, "environment_test_decoupled");
  expectFinite(both.forward, "EnvironmentTest forward");
  expectClean(both.decoupled, "EnvironmentTest decoupled");
  EXPECT_GT(meanLevel(both.forward.ldr), 20.0) << "not black";
  EXPECT_LT(meanLevel(both.forward.ldr), 230.0) << "not blown out";
  expectAgreement(both.decoupled, both.forward, {.psnr = 25.0, .meanAbs = 4.0}, "EnvironmentTest: decoupled vs forward");
}

}  // namespace
}  // namespace sg::test
