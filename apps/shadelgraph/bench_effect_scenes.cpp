#include "bench_effect_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/environment.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

namespace sg::app {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

int addMaterial(scene::Scene& s, scene::Material m) {
  s.materials.push_back(std::move(m));
  return int(s.materials.size() - 1);
}

void place(scene::Scene& s, scene::Primitive mesh, int material, const glm::mat4& world, const std::string& name) {
  mesh.material = material;
  scene::Mesh m;
  m.name = name;
  m.bounds = mesh.bounds;
  m.primitives.push_back(std::move(mesh));
  s.meshes.push_back(std::move(m));
  s.instances.push_back({.mesh = int(s.meshes.size() - 1), .world = world, .name = name});
}

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

scene::Camera camera(const glm::vec3& eye, const glm::vec3& target) {
  scene::Camera c{.name = "bench", .yfov = 0.8f, .znear = 0.1f, .zfar = 100.0f};
  c.world = scene::lookAtWorld(eye, target);
  return c;
}

scene::Material diffuse(const std::string& name, glm::vec3 color, float roughness = 0.7f) {
  return {.name = name, .baseColorFactor = glm::vec4(color, 1.0f), .metallicFactor = 0.0f, .roughnessFactor = roughness};
}

// Ground, two boxes, a sphere and a cylinder around the origin: casters and receivers.
scene::Scene courtyard() {
  scene::Scene s;
  const int ground = addMaterial(s, diffuse("ground", glm::vec3(0.6f)));
  const int stone = addMaterial(s, diffuse("stone", {0.7f, 0.62f, 0.5f}));
  const int paint = addMaterial(s, diffuse("paint", {0.25f, 0.4f, 0.7f}, 0.4f));
  place(s, scene::makePlane(12.0f, 12.0f, 8), ground, glm::mat4(1.0f), "ground");
  place(s, scene::makeBox({1.2f, 1.2f, 1.2f}), stone, glm::rotate(at(-1.5f, 0.6f, -0.5f), 0.5f, {0, 1, 0}), "box");
  place(s, scene::makeBox({0.6f, 2.0f, 0.6f}), stone, at(1.8f, 1.0f, -1.5f), "pillar");
  place(s, scene::makeSphere(0.7f, 40, 20), paint, at(0.4f, 0.7f, 0.6f), "sphere");
  place(s, scene::makeCylinder(0.35f, 1.4f, 32), paint, at(-0.2f, 0.0f, -2.2f), "cylinder");
  s.cameras.push_back(camera({0.0f, 3.2f, 6.5f}, {0.0f, 0.6f, -0.5f}));
  return s;
}

}  // namespace

std::string lightTypeName(scene::LightType type) {
  return type == scene::LightType::Directional ? "directional" : type == scene::LightType::Spot ? "spot" : "point";
}

scene::Scene shadowBenchScene(scene::LightType type, uint32_t lights, uint32_t shadowed) {
  scene::Scene s = courtyard();
  for (uint32_t i = 0; i < lights; ++i) {
    // Spread around the set: azimuths a quarter turn apart, offset so no two coincide.
    const float azimuth = 0.6f + 2.0f * kPi * float(i) / float(std::max(lights, 1u));
    const glm::vec3 around{std::cos(azimuth), 0.0f, std::sin(azimuth)};
    scene::Light l{.name = lightTypeName(type) + " " + std::to_string(i), .type = type, .shadows = i < shadowed};
    if (type == scene::LightType::Directional) {
      l.intensity = 3.0f / float(lights);  // lux: the same total at every count
      l.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.0f) - 0.8f * around);
    } else {
      l.position = 3.5f * around + glm::vec3(0.0f, 3.5f, 0.0f);
      l.direction = glm::normalize(glm::vec3(0.0f, 0.5f, -0.5f) - l.position);
      l.intensity = 40.0f / float(lights);  // candela
      l.range = 14.0f;
      l.innerConeAngle = 0.35f;
      l.outerConeAngle = 0.7f;
    }
    s.lights.push_back(l);
  }
  return s;
}

scene::Scene manyLightsBenchScene(uint32_t count) {
  scene::Scene s;
  const float width = 14.0f, depth = 10.0f;
  const int floor = addMaterial(s, diffuse("floor", glm::vec3(0.7f), 0.5f));
  const int wall = addMaterial(s, diffuse("wall", {0.6f, 0.58f, 0.55f}));
  const int crate = addMaterial(s, diffuse("crate", {0.55f, 0.4f, 0.25f}));
  const int ball = addMaterial(s, diffuse("ball", glm::vec3(0.8f), 0.3f));
  place(s, scene::makePlane(width, depth, 16), floor, glm::mat4(1.0f), "floor");
  place(s, scene::makeBox({width, 3.0f, 0.2f}), wall, at(0.0f, 1.5f, -depth / 2), "back wall");
  for (int i = 0; i < 5; ++i)
    place(s, scene::makeBox(glm::vec3(1.0f)), crate,
          glm::rotate(at(-4.0f + 2.0f * float(i), 0.5f, i % 2 ? -2.0f : 1.5f), 0.35f * float(i), {0, 1, 0}),
          "crate " + std::to_string(i));
  place(s, scene::makeSphere(0.8f, 40, 20), ball, at(0.0f, 0.8f, 0.0f), "sphere");
  // A grid as square as the floor allows, jittered by a fixed hash (the same lights every run).
  const auto columns = uint32_t(std::max(1.0f, std::round(std::sqrt(float(count) * width / depth))));
  const uint32_t rows = (count + columns - 1) / columns;
  const float area = width * depth;
  const float range = std::sqrt(kLightsInReach * area / (kPi * float(count)));
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t c = i % columns, r = i / columns;
    const float jx = float((i * 2654435761u) % 1000u) / 1000.0f - 0.5f;
    const float jz = float((i * 40503u + 17u) % 1000u) / 1000.0f - 0.5f;
    const glm::vec3 hue{0.5f + 0.5f * std::cos(float(i) * 0.9f), 0.5f + 0.5f * std::cos(float(i) * 0.9f + 2.1f),
                        0.5f + 0.5f * std::cos(float(i) * 0.9f + 4.2f)};
    s.lights.push_back({.name = "bulb " + std::to_string(i),
                        .type = scene::LightType::Point,
                        .color = glm::mix(glm::vec3(1.0f), hue, 0.6f),
                        .intensity = 0.25f * range * range,  // candela: about the same light at a floor point at every count
                        .range = range,
                        .position = {-width / 2 + width * (float(c) + 0.5f + 0.6f * jx) / float(columns),
                                     0.35f + 0.5f * float(i % 7) / 6.0f,
                                     -depth / 2 + depth * (float(r) + 0.5f + 0.6f * jz) / float(rows)},
                        .shadows = false});
  }
  s.cameras.push_back(camera({0.0f, 4.0f, 8.5f}, {0.0f, 0.3f, -1.0f}));
  return s;
}

scene::Scene iblBenchScene(const std::filesystem::path& environment) {
  scene::Scene s;
  place(s, scene::makePlane(10.0f, 10.0f, 8), addMaterial(s, diffuse("ground", glm::vec3(0.5f))), glm::mat4(1.0f),
        "ground");
  for (int metal = 0; metal < 2; ++metal)
    for (int r = 0; r < 4; ++r) {
      const float roughness = 0.1f + 0.3f * float(r);
      const int m = addMaterial(s, {.name = "sphere " + std::to_string(metal) + std::to_string(r),
                                    .baseColorFactor = metal ? glm::vec4(0.95f, 0.75f, 0.4f, 1.0f) : glm::vec4(0.7f, 0.15f, 0.1f, 1.0f),
                                    .metallicFactor = float(metal),
                                    .roughnessFactor = roughness});
      place(s, scene::makeSphere(0.45f, 40, 20), m, at(-1.65f + 1.1f * float(r), 0.45f, metal ? -1.2f : 0.0f),
            "sphere " + std::to_string(metal * 4 + r));
    }
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
                      .direction = glm::normalize(glm::vec3(-0.7f, -0.84f, 0.7f)), .shadows = false});
  if (!environment.empty()) s.environment = scene::loadEnvironment(environment, 1.0f);
  s.cameras.push_back(camera({0.0f, 1.8f, 3.6f}, {0.0f, 0.35f, -0.6f}));
  return s;
}

scene::Scene bloomBenchScene(float emission) {
  scene::Scene s = courtyard();
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
                      .direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.5f)), .shadows = false});
  const int glow = addMaterial(s, {.name = "glow", .metallicFactor = 0.0f, .emissiveFactor = {1.0f, 0.8f, 0.5f},
                                   .emissiveStrength = emission});
  place(s, scene::makeBox({0.5f, 0.5f, 0.5f}), glow, at(1.4f, 0.25f, 0.8f), "glow");
  return s;
}

}  // namespace sg::app
