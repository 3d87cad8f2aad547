// Environment light (issue 16, "Environment light"): a scene naming an
// equirectangular HDR image is lit by it (image-based lighting from the
// one-time prefilter), the same in the forward fragment variant and the
// decoupled compute variant of a material (gltf-pbr, split-pbr), and the
// sample asset EnvironmentTest renders under it. The test image is the
// procedural sky of benchmarks/environment/procedural_sky.hpp (no HDR environment ships
// with the sample assets or Debian).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

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
                         [](const auto& info) { return std::string(info.param) == "gltf-pbr" ? "GltfPbr" : "SplitPbr"; });

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
    EXPECT_GT(bottom.r, 1.3f * bottom.b) << what << ": the lower half faces the brown ground";
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
