#include <shadelgraph/scene/default_scene.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>
#include <shadelgraph/scene/procedural_textures.hpp>

namespace sg::scene {
namespace {

int addTexture(Scene& s, Texture t) {
  t.sampler = 0;
  s.textures.push_back(std::move(t));
  return static_cast<int>(s.textures.size() - 1);
}

int addMaterial(Scene& s, Material m) {
  s.materials.push_back(std::move(m));
  return static_cast<int>(s.materials.size() - 1);
}

int addMesh(Scene& s, std::string name, Primitive p, int material) {
  p.material = material;
  Mesh mesh;
  mesh.name = std::move(name);
  mesh.bounds = p.bounds;
  mesh.primitives.push_back(std::move(p));
  s.meshes.push_back(std::move(mesh));
  return static_cast<int>(s.meshes.size() - 1);
}

void place(Scene& s, int mesh, std::string name, const glm::mat4& world) {
  s.instances.push_back({mesh, world, std::move(name), ShadingMode::Auto});
}

glm::mat4 at(float x, float y, float z) { return glm::translate(glm::mat4(1.0f), {x, y, z}); }

}  // namespace

Scene makeDefaultScene(uint32_t textureSize) {
  Scene s;
  s.samplers.push_back(Sampler{});
  const uint32_t n = textureSize;

  const int tilesColor = addTexture(s, makeTilesColor(n, 8));
  const int tilesNormal = addTexture(s, makeTilesNormal(n, 8));
  const int bricksColor = addTexture(s, makeBricksColor(n, 16));
  const int bricksNormal = addTexture(s, makeBricksNormal(n, 16));
  const int marble = addTexture(s, makeMarbleColor(n));
  const int ripples = addTexture(s, makeRipplesNormal(n, 48));
  const int checker = addTexture(s, makeCheckerColor(n, 16));

  Material ground{.name = "stone tiles", .metallicFactor = 0.0f, .roughnessFactor = 0.8f};
  ground.baseColorTexture.texture = tilesColor;
  ground.normalTexture.texture = tilesNormal;
  Material brick{.name = "brick", .metallicFactor = 0.0f, .roughnessFactor = 0.9f};
  brick.baseColorTexture.texture = bricksColor;
  brick.normalTexture.texture = bricksNormal;
  Material stone{.name = "marble", .metallicFactor = 0.0f, .roughnessFactor = 0.35f};
  stone.baseColorTexture.texture = marble;
  // The shimmer case: glossy gold with a normal pattern finer than a pixel at a distance.
  Material gold{.name = "rippled gold", .baseColorFactor = {1.0f, 0.78f, 0.34f, 1.0f}, .metallicFactor = 1.0f,
                .roughnessFactor = 0.18f};
  gold.normalTexture.texture = ripples;
  Material paint{.name = "painted checker", .metallicFactor = 0.0f, .roughnessFactor = 0.5f};
  paint.baseColorTexture.texture = checker;

  const int groundMat = addMaterial(s, ground), brickMat = addMaterial(s, brick), stoneMat = addMaterial(s, stone),
            goldMat = addMaterial(s, gold), paintMat = addMaterial(s, paint);

  place(s, addMesh(s, "ground", makePlane(16, 16, 16), groundMat), "ground", glm::mat4(1.0f));
  place(s, addMesh(s, "back wall", makeBox({16, 4, 0.5f}), brickMat), "back wall", at(0, 2, -8));
  place(s, addMesh(s, "side wall", makeBox({0.5f, 3, 16}), brickMat), "left wall", at(-8, 1.5f, 0));
  place(s, addMesh(s, "low wall", makeBox({0.5f, 1.5f, 8}), brickMat), "right wall", at(7, 0.75f, -3));
  const int pillar = addMesh(s, "pillar", makeCylinder(0.4f, 4.0f, 32), stoneMat);
  for (float x : {-4.0f, 4.0f})
    for (float z : {-5.0f, 1.0f}) place(s, pillar, "pillar", at(x, 0, z));
  place(s, addMesh(s, "gold sphere", makeSphere(1.2f, 64, 32), goldMat), "gold sphere", at(0, 1.2f, -1.5f));
  // It moves (frame 0 is the pose above): a 0.5-unit circle every 4 s, turning
  // 20 degrees a second, so multi-frame runs and benchmarks see object motion.
  s.instances.back().motion = {.type = ObjectMotion::Type::Orbit, .radius = 0.5f, .seconds = 4.0f,
                               .spinDegreesPerSecond = 20.0f, .pivot = {0.0f, 1.2f, -1.5f}};
  place(s, addMesh(s, "torus", makeTorus(1.0f, 0.35f, 48, 24), paintMat), "torus",
        glm::rotate(at(-2.6f, 1.35f, 1.2f), glm::radians(70.0f), {1, 0, 0}));
  place(s, addMesh(s, "crate", makeBox({1, 1, 1}), paintMat), "crate",
        glm::rotate(at(2.6f, 0.5f, -0.5f), glm::radians(30.0f), {0, 1, 0}));

  // The sun casts shadows (cascades); the two fill lamps do not (12 cube faces would double the frame on a CPU device).
  s.lights.push_back({.name = "sun", .type = LightType::Directional, .color = {1.0f, 0.93f, 0.82f},
                      .intensity = 2.5f, .direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.55f))});
  s.lights.push_back({.name = "warm lamp", .type = LightType::Point, .color = {1.0f, 0.6f, 0.3f},
                      .intensity = 12.0f, .position = {-3.0f, 2.5f, -3.0f}, .shadows = false});
  s.lights.push_back({.name = "cool lamp", .type = LightType::Point, .color = {0.4f, 0.6f, 1.0f},
                      .intensity = 10.0f, .position = {3.5f, 2.0f, 2.0f}, .shadows = false});

  Camera camera{.name = "courtyard", .yfov = 0.9f, .znear = 0.1f, .zfar = 100.0f};
  camera.world = lookAtWorld({1.5f, 3.2f, 8.5f}, {0.0f, 1.0f, -1.5f});
  s.cameras.push_back(camera);
  return s;
}

}  // namespace sg::scene
