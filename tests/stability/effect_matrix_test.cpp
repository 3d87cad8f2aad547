// The effect matrix (docs/composing-frames.md, "Effects the scene calls for"):
// for each scene of a matrix and each shading path, the compiled frame — what
// `shadelgraph graph --json` prints — holds exactly the effect passes and
// effect resources that scene calls for, and no others. A row is added for
// each effect as it lands.
#include <gtest/gtest.h>

#include <functional>
#include <set>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <shadelgraph/graph/plan_dump.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "procedural_sky.hpp"
#include "stability_checks.hpp"
#include "stability_scenes.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

using Names = std::set<std::string>;

// Passes present only when the scene calls for them.
const Names kEffectPasses = {"alpha-mask", "alpha-blend", "shadows", "environment-downsample", "environment-prefilter",
                              "environment-background", "bloom", "light-cull"};
// Graph resources that exist only for an effect (matched by name prefix).
const Names kEffectResourcePrefixes = {"shadow", "environment", "bloom", "hdr (bloom)", "light grid"};
const Names kPrefilterPasses = {"environment-downsample", "environment-prefilter"};
const Names kEnvironmentMaps = {"environment brdf", "environment irradiance", "environment specular"};
// Every frame of an environment scene draws the image behind everything, from the image itself.
const Names kEnvironmentBackground = {"environment-background"};
const Names kBloomResources = {"bloom level 1", "bloom level 2", "bloom level 3", "bloom level 4", "bloom level 5",
                               "hdr (bloom)"};

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

void addObject(scene::Scene& s, scene::Material m, const glm::mat4& world) {
  placeMesh(s, scene::makeBox({0.5f, 0.5f, 0.5f}), addMaterial(s, std::move(m)), world);
}

// A ground and a sphere on it, a material each; lights and extras added per row.
scene::Scene baseSet() {
  scene::Scene s;
  const int ground = addMaterial(s, {.name = "ground", .baseColorFactor = glm::vec4(0.6f), .metallicFactor = 0.0f});
  const int ball = addMaterial(s, {.name = "ball", .baseColorFactor = {0.8f, 0.3f, 0.2f, 1.0f},
                                   .metallicFactor = 0.0f, .roughnessFactor = 0.5f});
  placeMesh(s, scene::makePlane(6.0f, 6.0f, 4), ground, glm::mat4(1.0f));
  placeMesh(s, scene::makeSphere(0.6f, 24, 12), ball, at(0.0f, 0.6f, 0.0f));
  s.cameras.push_back(cameraAt({0.0f, 2.5f, 4.5f}, {0.0f, 0.4f, 0.0f}));
  return s;
}

scene::Light sun(bool shadows) {
  return {.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
          .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f)), .shadows = shadows};
}

scene::Light bulb(bool shadows, glm::vec3 position = {0.8f, 2.0f, 0.5f}, float range = 0.0f) {
  return {.name = "bulb", .type = scene::LightType::Point, .intensity = 20.0f, .range = range,
          .position = position, .shadows = shadows};
}

scene::Light spot(bool shadows) {
  return {.name = "spot", .type = scene::LightType::Spot, .intensity = 30.0f, .innerConeAngle = 0.3f,
          .outerConeAngle = 0.6f, .position = {0.0f, 3.0f, 1.0f},
          .direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.3f)), .shadows = shadows};
}

// A shadowed spot lighting a box far behind the camera: it reaches no visible object.
scene::Scene spotBehindTheCamera() {
  auto s = baseSet();
  s.lights.push_back(sun(false));
  addObject(s, {.name = "far box", .metallicFactor = 0.0f}, at(0.0f, 0.25f, 30.0f));
  scene::Light l = spot(true);
  l.position = {0.0f, 3.0f, 30.0f};
  l.direction = {0.0f, -1.0f, 0.0f};
  l.range = 5.0f;
  s.lights.push_back(l);
  return s;
}

// Under the sun, lit by a procedural sky image too (environment light).
scene::Scene environmentLit() {
  auto s = baseSet();
  s.lights.push_back(sun(false));
  TempDir dir;
  bench::writeProceduralSky(dir.path() / "sky.hdr", 64, 32);
  s.environment = scene::loadEnvironment(dir.path() / "sky.hdr", 1.0f);
  return s;
}

// A box emitting `strength` cd/m^2 (white emissive factor) in view.
scene::Scene glowing(float strength) {
  auto s = baseSet();
  s.lights.push_back(sun(false));
  addObject(s, {.name = "glow", .metallicFactor = 0.0f, .emissiveFactor = glm::vec3(1.0f),
                .emissiveStrength = strength},
            at(1.2f, 0.25f, 0.5f));
  return s;
}

Names with(Names a, const Names& b) {
  a.insert(b.begin(), b.end());
  return a;
}

struct Row {
  std::string name;
  std::function<scene::Scene()> scene;
  Names forwardPasses, decoupledPasses;  // the effect passes each path holds
  Names resources;                        // effect resources (both paths)
  std::string atlas = "";                 // the shadow atlas's size, when there is one: maps of 1024² 4 a row
};

std::vector<Row> matrix() {
  return {
      {"NoLights", [] { return baseSet(); }, {}, {}, {}},
      {"ShadowedSun", [] { auto s = baseSet(); s.lights.push_back(sun(true)); return s; }, {"shadows"}, {"shadows"},
       {"shadow atlas"}, "4096x1024"},  // its 4 cascades
      {"UnshadowedSun", [] { auto s = baseSet(); s.lights.push_back(sun(false)); return s; }, {}, {}, {}},
      {"ShadowedSpot", [] { auto s = baseSet(); s.lights.push_back(spot(true)); return s; }, {"shadows"},
       {"shadows"}, {"shadow atlas"}, "1024x1024"},
      {"ShadowedPoint", [] { auto s = baseSet(); s.lights.push_back(bulb(true)); return s; }, {"shadows"},
       {"shadows"}, {"shadow atlas"}, "4096x2048"},  // its 6 cube faces
      {"UnshadowedPoint", [] { auto s = baseSet(); s.lights.push_back(bulb(false)); return s; }, {}, {}, {}},
      {"ShadowedPointReachingNothingVisible",
       [] { auto s = baseSet(); s.lights.push_back(bulb(true, {0.0f, 2.0f, 30.0f}, 5.0f)); return s; }, {}, {}, {}},
      // Many lights: above light-cull's threshold the frame culls them per cluster (docs/many-lights.md).
      {"ThreeHundredPointLights", [] { return makeLitSetWithPointLights(300); }, {"light-cull"}, {"light-cull"},
       {"light grid"}},
      {"EightPointLights", [] { return makeLitSetWithPointLights(8); }, {}, {}, {}},
      {"SunSpotAndPoint",
       [] {
         auto s = baseSet();
         s.lights = {sun(true), spot(true), bulb(true)};
         return s;
       },
       {"shadows"}, {"shadows"}, {"shadow atlas"}, "4096x3072"},  // 4 + 1 + 6 maps
      {"UnshadowedSpot", [] { auto s = baseSet(); s.lights.push_back(spot(false)); return s; }, {}, {}, {}},
      {"ShadowedSpotReachingNothingVisible", spotBehindTheCamera, {}, {}, {}},
      // Bloom: a visible object emitting at least the bloom threshold (10 cd/m^2).
      {"Emissive", [] { return glowing(50.0f); }, {"bloom"}, {"bloom"}, kBloomResources},
      {"DimEmissive", [] { return glowing(5.0f); }, {}, {}, {}},
      // Environment light: the first frame prefilters the image into the three maps; every frame draws it behind.
      {"Environment", environmentLit, with(kPrefilterPasses, kEnvironmentBackground),
       with(kPrefilterPasses, kEnvironmentBackground), with(kEnvironmentMaps, {"environment image"})},
      {"AlphaBlend",
       [] {
         auto s = baseSet();
         s.lights.push_back(sun(false));
         addObject(s, {.name = "glass", .baseColorFactor = {0.5f, 0.7f, 1.0f, 0.4f}, .metallicFactor = 0.0f,
                       .alphaMode = scene::AlphaMode::Blend},
                   at(-1.2f, 0.25f, 0.5f));
         return s;
       },
       {"alpha-blend"}, {"alpha-blend"}, {}},
      {"AlphaMask",
       [] {
         auto s = baseSet();
         s.lights.push_back(sun(false));
         addObject(s, {.name = "leaf", .baseColorFactor = {0.3f, 0.8f, 0.3f, 0.4f}, .metallicFactor = 0.0f,
                       .alphaMode = scene::AlphaMode::Mask},
                   at(-1.2f, 0.25f, 0.5f));
         return s;
       },
       {"alpha-mask"}, {}, {}},  // decoupled: shadel-mark and composite alpha-test it, no pass of its own
  };
}

// The effect passes and resources of a compiled frame, read from its JSON dump.
struct Effects {
  Names passes, resources;
  std::string atlas;
  bool forwardOpaque = false;
};
Effects effectsOf(const nlohmann::json& plan) {
  Effects e;
  for (const auto& p : plan["passes"]) {
    const auto name = p["name"].get<std::string>();
    if (!p["culled"].get<bool>() && kEffectPasses.count(name)) e.passes.insert(name);
    if (!p["culled"].get<bool>() && name == "forward-opaque") e.forwardOpaque = true;
  }
  for (const auto& r : plan["resources"]) {
    const auto name = r["name"].get<std::string>();
    // The harness's own copies (hdr-capture, light-grid-capture) are not the frame's.
    if (r["culled"].get<bool>() || name.ends_with("(captured)")) continue;
    for (const auto& prefix : kEffectResourcePrefixes)
      if (name.rfind(prefix, 0) == 0) e.resources.insert(name);
    if (name == "shadow atlas")
      e.atlas = std::to_string(r["width"].get<uint32_t>()) + "x" + std::to_string(r["height"].get<uint32_t>());
  }
  return e;
}

std::string joined(const Names& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return "{" + out + "}";
}

struct Case {
  Row row;
  scene::ShadingMode mode;
};

class EffectMatrix : public ::testing::TestWithParam<Case> {};

TEST_P(EffectMatrix, TheFrameHoldsExactlyTheEffectsTheSceneCallsFor) {
  const Case& c = GetParam();
  StabilitySession session(c.row.scene(), c.mode);
  const auto plan = nlohmann::json::parse(graph::toJson(session.plan(96, 64)));
  const Effects got = effectsOf(plan);
  const bool forward = c.mode == scene::ShadingMode::Forward;
  const Names& expected = forward ? c.row.forwardPasses : c.row.decoupledPasses;
  std::printf("%-34s %-9s passes %s resources %s\n", c.row.name.c_str(), forward ? "forward" : "decoupled",
              joined(got.passes).c_str(), joined(got.resources).c_str());
  EXPECT_EQ(got.passes, expected) << "got " << joined(got.passes) << ", expected " << joined(expected);
  EXPECT_EQ(got.resources, c.row.resources)
      << "got " << joined(got.resources) << ", expected " << joined(c.row.resources);
  EXPECT_EQ(got.atlas, c.row.atlas) << "the shadow atlas's size";
  // Decoupled, no row has an opaque object shaded forward (blended ones are,
  // drawn by alpha-blend): forward-opaque would draw nothing, composite clears.
  EXPECT_EQ(got.forwardOpaque, forward) << "forward-opaque";
}

// The prefilter is one-time: after a frame has run it, the next frames hold
// the maps (persistent) and no prefilter pass; the image stays for the background.
TEST(EffectMatrixEnvironment, ThePrefilterRunsInTheFirstFrameOnly) {
  for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) {
    const char* what = mode == scene::ShadingMode::Forward ? "forward" : "decoupled";
    StabilitySession session(environmentLit(), mode);
    session.render(96, 64);
    const Effects got = effectsOf(nlohmann::json::parse(graph::toJson(session.plan(96, 64))));
    EXPECT_EQ(got.passes, kEnvironmentBackground) << what << ": got " << joined(got.passes);
    EXPECT_EQ(got.resources, with(kEnvironmentMaps, {"environment image"})) << what << ": got " << joined(got.resources);
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const Row& r : matrix())
    for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) out.push_back({r, mode});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, EffectMatrix, ::testing::ValuesIn(cases()), [](const auto& param_info) {
  return param_info.param.row.name + (param_info.param.mode == scene::ShadingMode::Forward ? "_Forward" : "_Decoupled");
});

}  // namespace
}  // namespace sg::test
