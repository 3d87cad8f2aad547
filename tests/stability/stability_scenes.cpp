#include "stability_scenes.hpp"

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>
#include <shadelgraph/scene/procedural_textures.hpp>

namespace sg::test {
namespace {

int addTexture(scene::Scene& s, scene::Texture t) {
  if (s.samplers.empty()) s.samplers.push_back(scene::Sampler{});
  t.sampler = 0;
  s.textures.push_back(std::move(t));
  return int(s.textures.size() - 1);
}

// Tiles (colour and normal map): the material every geometry case shades.
int addTilesMaterial(scene::Scene& s, uint32_t textureSize) {
  scene::Material m{.name = "tiles", .metallicFactor = 0.0f, .roughnessFactor = 0.6f};
  m.baseColorTexture.texture = addTexture(s, scene::makeTilesColor(textureSize, 8));
  m.normalTexture.texture = addTexture(s, scene::makeTilesNormal(textureSize, 8));
  return addMaterial(s, m);
}

// Both shadowed (the default): the sun's cascades and the lamp's cube maps go wherever the set goes, far away or scaled.
void addLights(scene::Scene& s) {
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .color = {1.0f, 0.95f, 0.85f},
                      .intensity = 2.5f, .direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.6f))});
  s.lights.push_back({.name = "lamp", .type = scene::LightType::Point, .color = {0.5f, 0.7f, 1.0f},
                      .intensity = 8.0f, .position = {2.5f, 2.0f, 2.0f}});
}

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

}  // namespace

int addMaterial(scene::Scene& s, scene::Material material) {
  s.materials.push_back(std::move(material));
  return int(s.materials.size() - 1);
}

void placeMesh(scene::Scene& s, scene::Primitive mesh, int material, const glm::mat4& world) {
  mesh.material = material;
  scene::Mesh m;
  m.name = "mesh " + std::to_string(s.meshes.size());
  m.bounds = mesh.bounds;
  m.primitives.push_back(std::move(mesh));
  s.meshes.push_back(std::move(m));
  s.instances.push_back({.mesh = int(s.meshes.size() - 1), .world = world,
                         .name = "object " + std::to_string(s.instances.size())});
}

scene::Scene makeLitSet(uint32_t textureSize) {
  scene::Scene s;
  const int tiles = addTilesMaterial(s, textureSize);
  scene::Material bricks{.name = "bricks", .metallicFactor = 0.0f, .roughnessFactor = 0.8f};
  bricks.baseColorTexture.texture = addTexture(s, scene::makeBricksColor(textureSize, 8));
  bricks.normalTexture.texture = addTexture(s, scene::makeBricksNormal(textureSize, 8));
  scene::Material stone{.name = "marble", .metallicFactor = 0.0f, .roughnessFactor = 0.3f};
  stone.baseColorTexture.texture = addTexture(s, scene::makeMarbleColor(textureSize));
  const int bricksMat = addMaterial(s, bricks), stoneMat = addMaterial(s, stone);
  placeMesh(s, scene::makePlane(8.0f, 8.0f, 8), tiles, glm::mat4(1.0f));
  placeMesh(s, scene::makeBox({1.5f, 1.5f, 1.5f}), bricksMat,
            glm::rotate(at(-1.2f, 0.75f, 0.0f), glm::radians(30.0f), {0.0f, 1.0f, 0.0f}));
  placeMesh(s, scene::makeSphere(1.0f, 48, 24), stoneMat, at(1.4f, 1.0f, -0.6f));
  addLights(s);
  s.cameras.push_back(cameraAt({0.5f, 3.0f, 6.0f}, {0.0f, 0.6f, 0.0f}));
  return s;
}

scene::Scene makeLitSetWithPointLights(uint32_t count) {
  scene::Scene s = makeLitSet();
  s.lights.clear();
  const auto side = uint32_t(std::ceil(std::sqrt(float(count))));
  for (uint32_t i = 0; i < count; ++i) {
    const float u = float(i % side) / float(side - 1), v = float(i / side) / float(side - 1);
    const glm::vec3 hue = glm::abs(glm::fract(float(i) * 0.137f + glm::vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 2.0f - 1.0f);
    s.lights.push_back({.name = "bulb " + std::to_string(i), .type = scene::LightType::Point,
                        .color = glm::mix(glm::vec3(1.0f), hue, 0.6f), .intensity = 0.4f, .range = 1.2f,
                        .position = {8.0f * u - 4.0f, 0.2f + 0.5f * float(i % 5) / 4.0f, 8.0f * v - 4.0f},
                        .shadows = false});  // what is measured is culling, not 300 cube maps
  }
  return s;
}

scene::Scene makeSingleMesh(scene::Primitive mesh, uint32_t textureSize) {
  scene::Scene s;
  placeMesh(s, std::move(mesh), addTilesMaterial(s, textureSize), glm::mat4(1.0f));
  addLights(s);
  return s;
}

scene::Camera cameraAt(const glm::vec3& eye, const glm::vec3& target, float znear, float zfar, float yfov) {
  scene::Camera c{.name = "stability", .yfov = yfov, .znear = znear, .zfar = zfar};
  c.world = scene::lookAtWorld(eye, target);
  return c;
}

scene::Camera translated(scene::Camera camera, const glm::dvec3& offset) {
  camera.world = glm::mat4(glm::translate(glm::dmat4(1.0), offset) * glm::dmat4(camera.world));
  return camera;
}

void translateScene(scene::Scene& s, const glm::dvec3& offset) {
  const glm::dmat4 move = glm::translate(glm::dmat4(1.0), offset);
  for (auto& instance : s.instances) instance.world = glm::mat4(move * glm::dmat4(instance.world));
  for (auto& light : s.lights) light.position = glm::vec3(glm::dvec3(light.position) + offset);
  for (auto& camera : s.cameras) camera = translated(camera, offset);
}

scene::Camera scaled(scene::Camera camera, float factor) {
  camera.world[3] = glm::vec4(glm::vec3(camera.world[3]) * factor, 1.0f);
  camera.znear *= factor;
  if (camera.zfar) *camera.zfar *= factor;
  camera.xmag *= factor;
  camera.ymag *= factor;
  return camera;
}

void scaleScene(scene::Scene& s, float factor) {
  const glm::mat4 scale = glm::scale(glm::mat4(1.0f), glm::vec3(factor));
  for (auto& instance : s.instances) instance.world = scale * instance.world;
  for (auto& light : s.lights) {
    light.position *= factor;
    if (light.type != scene::LightType::Directional) light.intensity *= factor * factor;
    light.range *= factor;
  }
  for (auto& camera : s.cameras) camera = scaled(camera, factor);
}

}  // namespace sg::test
