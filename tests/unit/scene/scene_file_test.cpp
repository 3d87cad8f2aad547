// Scene files, camera paths, camera framing.
#include <cmath>
#include <numbers>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <shadelgraph/scene/camera.hpp>
#include <shadelgraph/scene/scene_file.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

constexpr float kEps = 1e-4f;

std::string loadError(const std::filesystem::path& file) {
  try {
    loadSceneFile(file);
  } catch (const SceneError& error) {
    return error.what();
  }
  ADD_FAILURE() << file << " loaded";
  return {};
}

// A scene directory: models/triangle.gltf (one mesh node, shading "forward"
// in its extras) and scene.json with `body`.
std::filesystem::path writeScene(const TempDir& dir, const std::string& body) {
  const std::filesystem::path models = dir.path() / "models";
  std::filesystem::create_directories(models);
  dir.write("models/triangle.bin", test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  dir.write("models/triangle.gltf", R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "tri", "mesh": 0, "translation": [0, 0, -1], "extras": {"shading": "forward"}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "buffers": [{"uri": "triangle.bin", "byteLength": 36}]})");
  return dir.write("scene.json", body);
}

TEST(SceneFile, ObjectsLightsAndPaths) {
  TempDir dir;
  const auto file = writeScene(dir, R"({
  "objects": [
    {"gltf": "models/triangle.gltf", "name": "a", "translation": [10, 0, 0], "shading": "decoupled"},
    {"gltf": "models/triangle.gltf", "rotationDegrees": [0, 90, 0], "scale": 2},
    {"gltf": "models/triangle.gltf", "name": "c", "rotation": [0, 0, 0.70710678, 0.70710678], "scale": [1, 3, 1]}
  ],
  "lights": [
    {"type": "directional", "direction": [0, -2, 0], "intensity": 3, "name": "sun"},
    {"type": "spot", "position": [0, 3, 0], "innerConeAngle": 0.1, "outerConeAngle": 0.4, "shadows": false}
  ],
  "cameraPaths": [
    {"name": "spin", "type": "orbit", "center": [0, 1, 0], "radius": 4, "height": 2, "seconds": 8},
    {"type": "keys", "keys": [{"t": 0, "position": [0, 0, 5], "target": [0, 0, 0]},
                              {"t": 2, "position": [5, 0, 0], "target": [0, 0, 0]}]}
  ]})");
  const SceneFile loaded = loadSceneFile(file);
  const Scene& scene = loaded.scene;
  ASSERT_EQ(scene.instances.size(), 3u);
  ASSERT_EQ(scene.meshes.size(), 1u) << "a glTF's meshes are stored once however many objects place it";
  for (const Instance& instance : scene.instances) EXPECT_EQ(instance.mesh, 0);

  const Instance& a = scene.instances[0];
  EXPECT_EQ(a.name, "a/tri");
  EXPECT_EQ(a.shading, ShadingMode::Decoupled) << "the scene file overrides the node's extras";
  EXPECT_EQ(glm::vec3(a.world[3]), glm::vec3(10, 0, -1)) << "object transform on top of the node's";

  const Instance& b = scene.instances[1];
  EXPECT_EQ(b.name, "triangle/tri") << "unnamed objects use the file's stem";
  EXPECT_EQ(b.shading, ShadingMode::Forward) << "from the glTF node extras";
  // Yaw 90°: -Z (the node's offset) turns to -X, doubled by the scale.
  EXPECT_NEAR(glm::distance(glm::vec3(b.world[3]), glm::vec3(-2, 0, 0)), 0.0f, kEps);

  const Instance& c = scene.instances[2];
  // Quarter turn about Z after scaling y by 3: the local x axis becomes +y.
  EXPECT_NEAR(glm::distance(glm::vec3(c.world * glm::vec4(1, 0, 0, 0)), glm::vec3(0, 1, 0)), 0.0f, kEps);
  EXPECT_NEAR(glm::distance(glm::vec3(c.world * glm::vec4(0, 1, 0, 0)), glm::vec3(-3, 0, 0)), 0.0f, kEps);

  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_EQ(scene.lights[0].type, LightType::Directional);
  EXPECT_EQ(scene.lights[0].direction, glm::vec3(0, -1, 0));
  EXPECT_FLOAT_EQ(scene.lights[0].intensity, 3.0f);
  EXPECT_EQ(scene.lights[1].type, LightType::Spot);
  EXPECT_FLOAT_EQ(scene.lights[1].outerConeAngle, 0.4f);
  EXPECT_TRUE(scene.lights[0].shadows) << "the default";
  EXPECT_FALSE(scene.lights[1].shadows);

  ASSERT_EQ(loaded.cameraPaths.size(), 2u);
  EXPECT_EQ(loaded.cameraPaths[0].name, "spin");
  EXPECT_EQ(loaded.cameraPaths[0].type, CameraPath::Type::Orbit);
  EXPECT_FLOAT_EQ(loaded.cameraPaths[0].duration(), 8.0f);
  EXPECT_EQ(loaded.cameraPaths[1].name, "path 1");
  EXPECT_EQ(loaded.cameraPaths[1].keys.size(), 2u);
  EXPECT_FLOAT_EQ(loaded.cameraPaths[1].duration(), 2.0f);
}

TEST(SceneFile, SampleModelsTogether) {
  SG_REQUIRE_ASSETS();
  TempDir dir;
  const std::string assets = test::assetsDir().string();
  const auto file = dir.write("scene.json", R"({"objects": [
    {"gltf": ")" + assets + R"(/BoxTextured/glTF/BoxTextured.gltf"},
    {"gltf": ")" + assets + R"(/Duck/glTF/Duck.gltf", "translation": [3, 0, 0]},
    {"gltf": ")" + assets + R"(/BoxTextured/glTF/BoxTextured.gltf", "translation": [-3, 0, 0]}]})");
  const Scene scene = loadSceneFile(file, LoadOptions{.decodeImages = false}).scene;
  EXPECT_EQ(scene.instances.size(), 3u);
  EXPECT_EQ(scene.textures.size(), 2u) << "BoxTextured's texture once, the duck's";
  EXPECT_EQ(scene.instances[0].mesh, scene.instances[2].mesh);
  // Indices were re-based: the duck's primitive uses the duck's material and texture.
  const Primitive& duck = scene.meshes[static_cast<size_t>(scene.instances[1].mesh)].primitives.at(0);
  const Material& material = scene.materials.at(static_cast<size_t>(duck.material));
  EXPECT_EQ(scene.textures.at(static_cast<size_t>(material.baseColorTexture.texture)).name, "DuckCM.png");
}

TEST(SceneFile, Errors) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.path() / "absent.json"), HasSubstr("cannot open"));
  EXPECT_THAT(loadError(writeScene(dir, "{")), HasSubstr("invalid JSON"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [{"gltf": "models/triangle.gltf", "shadng": "forward"}]})")),
              HasSubstr("/objects/0: unknown property 'shadng'"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [{"gltf": "models/triangle.gltf", "shading": "sometimes"}]})")),
              HasSubstr("/objects/0/shading: expected \"auto\", \"decoupled\" or \"forward\""));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [{"gltf": "models/absent.gltf"}]})")),
              HasSubstr("/objects/0/gltf: "));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [{"gltf": "models/absent.gltf"}]})")), HasSubstr("no such file"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [{"gltf": "models/triangle.gltf", "rotation": [0, 0, 0, 1],
                                                          "rotationDegrees": [0, 0, 0]}]})")),
              HasSubstr("not both"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [], "cameraPaths": [{"type": "orbit"}]})")),
              HasSubstr("/cameraPaths/0/radius: required property is missing"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [], "cameraPaths": [{"type": "keys", "keys": [
                 {"t": 1, "position": [0, 0, 1], "target": [0, 0, 0]}, {"t": 1, "position": [0, 0, 2], "target": [0, 0, 0]}]}]})")),
              HasSubstr("/cameraPaths/0/keys/1/t: key times must increase strictly"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [], "lights": [{"type": "area"}]})")),
              HasSubstr("/lights/0/type"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [], "lights": [{"type": "spot", "shadows": 1}]})")),
              HasSubstr("/lights/0/shadows: expected true or false"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"objects": [{"gltf": "models/triangle.gltf", "scale": "big"}]})")),
              HasSubstr("/objects/0/scale"));
  EXPECT_THAT(loadError(writeScene(dir, R"({"lights": []})")), HasSubstr("/objects: expected an array"));
}

TEST(CameraPath, OrbitGoesRoundItsCenter) {
  CameraPath orbit;
  orbit.type = CameraPath::Type::Orbit;
  orbit.center = {0, 1, 0};
  orbit.radius = 4;
  orbit.height = 2;
  orbit.seconds = 8;
  const CameraPose start = evaluatePose(orbit, 0.0f);
  EXPECT_NEAR(glm::distance(start.position, glm::vec3(0, 3, 4)), 0.0f, kEps);
  EXPECT_EQ(start.target, orbit.center);
  EXPECT_NEAR(glm::distance(evaluatePose(orbit, 2.0f).position, glm::vec3(4, 3, 0)), 0.0f, kEps) << "a quarter turn";
  EXPECT_NEAR(glm::distance(evaluatePose(orbit, 8.0f).position, start.position), 0.0f, kEps) << "periodic";
  // The view matrix puts the center straight ahead (on -Z) at the eye's distance.
  const glm::mat4 view = evaluateView(orbit, 1.3f);
  const glm::vec3 center = glm::vec3(view * glm::vec4(orbit.center, 1.0f));
  EXPECT_NEAR(center.x, 0.0f, kEps);
  EXPECT_NEAR(center.y, 0.0f, kEps);
  EXPECT_NEAR(center.z, -std::sqrt(4.0f * 4.0f + 2.0f * 2.0f), kEps);
}

TEST(CameraPath, KeysInterpolateThroughEveryKey) {
  CameraPath path;
  path.type = CameraPath::Type::Keys;
  path.keys = {{0.0f, {0, 0, 5}, {0, 0, 0}}, {1.0f, {5, 0, 5}, {1, 0, 0}}, {3.0f, {5, 0, 0}, {1, 1, 0}}, {4.0f, {0, 2, 0}, {0, 0, 0}}};
  for (const CameraKey& key : path.keys) {
    const CameraPose pose = evaluatePose(path, key.time);
    EXPECT_NEAR(glm::distance(pose.position, key.position), 0.0f, kEps) << key.time;
    EXPECT_NEAR(glm::distance(pose.target, key.target), 0.0f, kEps) << key.time;
  }
  // Held before the first key and after the last.
  EXPECT_EQ(evaluatePose(path, -1.0f).position, path.keys.front().position);
  EXPECT_EQ(evaluatePose(path, 9.0f).position, path.keys.back().position);
  // Continuous: small steps move the camera a little.
  glm::vec3 previous = evaluatePose(path, 0.0f).position;
  for (float t = 0.01f; t <= 4.0f; t += 0.01f) {
    const glm::vec3 current = evaluatePose(path, t).position;
    EXPECT_LT(glm::distance(current, previous), 0.2f) << t;
    previous = current;
  }
  // The view at a key looks from its position to its target.
  const glm::mat4 view = evaluateView(path, 1.0f);
  const glm::vec3 target = glm::vec3(view * glm::vec4(path.keys[1].target, 1.0f));
  EXPECT_NEAR(glm::length(glm::vec2(target)), 0.0f, kEps);
  EXPECT_LT(target.z, 0.0f);
}

TEST(CameraPath, TwoKeysAreAStraightLine) {
  CameraPath path;
  path.type = CameraPath::Type::Keys;
  path.keys = {{0.0f, {0, 0, 0}, {0, 0, -1}}, {2.0f, {4, 0, 0}, {4, 0, -1}}};
  EXPECT_NEAR(glm::distance(evaluatePose(path, 0.5f).position, glm::vec3(1, 0, 0)), 0.0f, kEps);
  EXPECT_NEAR(glm::distance(evaluatePose(path, 1.0f).position, glm::vec3(2, 0, 0)), 0.0f, kEps);
}

TEST(CameraPath, LookingStraightDownStillHasAView) {
  CameraPath path;
  path.type = CameraPath::Type::Keys;
  path.keys = {{0.0f, {0, 10, 0}, {0, 0, 0}}};
  const glm::mat4 view = evaluateView(path, 0.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_TRUE(std::isfinite(view[c][r]));
  EXPECT_NEAR(glm::distance(glm::vec3(view * glm::vec4(0, 0, 0, 1)), glm::vec3(0, 0, -10)), 0.0f, kEps);
}

// Every corner of `bounds` lands inside the clip volume of `camera`.
void expectInsideFrustum(const Camera& camera, const Bounds& bounds, float aspect) {
  const glm::mat4 clipFromWorld = camera.projectionMatrix(aspect) * camera.view();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 p{(corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                      (corner & 4) ? bounds.max.z : bounds.min.z};
    const glm::vec4 clip = clipFromWorld * glm::vec4(p, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    EXPECT_LE(std::abs(clip.x), clip.w) << corner;
    EXPECT_LE(std::abs(clip.y), clip.w) << corner;
    EXPECT_GE(clip.z, 0.0f) << corner;
    EXPECT_LE(clip.z, clip.w) << corner;
  }
}

TEST(Camera, FrameBoundsSeesEverything) {
  const Bounds boxes[] = {
      {glm::vec3(-1), glm::vec3(1)},
      {glm::vec3(100, 5, -3), glm::vec3(140, 6, 30)},  // flat and far from the origin
      {glm::vec3(-0.001f), glm::vec3(0.001f)},         // tiny
      {glm::vec3(-5, -500, -5), glm::vec3(5, 500, 5)},  // tall
  };
  for (const Bounds& bounds : boxes)
    for (float aspect : {0.5f, 1.0f, 16.0f / 9.0f, 3.0f}) {
      SCOPED_TRACE(testing::Message() << "aspect " << aspect << " size " << bounds.size().x);
      const Camera camera = frameBounds(bounds, aspect);
      expectInsideFrustum(camera, bounds, aspect);
      // And it looks at the center.
      const glm::vec3 center = glm::vec3(camera.view() * glm::vec4(bounds.center(), 1.0f));
      EXPECT_NEAR(glm::length(glm::vec2(center)) / std::abs(center.z), 0.0f, 1e-4f);
    }
}

TEST(Camera, FrameEmptyBounds) {
  const Camera camera = frameBounds(Bounds{}, 1.0f);
  EXPECT_EQ(camera.projection, Projection::Perspective);
  EXPECT_GT(camera.znear, 0.0f);
}

TEST(Camera, ProjectionConventions) {
  Camera camera;
  camera.yfov = std::numbers::pi_v<float> / 2;
  camera.znear = 1.0f;
  camera.zfar = 10.0f;
  const glm::mat4 projection = camera.projectionMatrix(2.0f);
  const auto ndc = [&](glm::vec3 p) {
    const glm::vec4 clip = projection * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
  };
  EXPECT_NEAR(ndc({0, 0, -1}).z, 0.0f, kEps) << "near plane at depth 0";
  EXPECT_NEAR(ndc({0, 0, -10}).z, 1.0f, kEps) << "far plane at depth 1";
  EXPECT_NEAR(ndc({0, 1, -1}).y, 1.0f, kEps) << "+Y up at the top of the 90° field of view";
  EXPECT_NEAR(ndc({2, 0, -1}).x, 1.0f, kEps) << "aspect 2 widens x";
  camera.zfar.reset();
  const glm::mat4 infinite = camera.projectionMatrix(2.0f);
  const glm::vec4 far = infinite * glm::vec4(0, 0, -1e6f, 1);
  EXPECT_NEAR(far.z / far.w, 1.0f, 1e-4f);
  const glm::vec4 near = infinite * glm::vec4(0, 0, -1, 1);
  EXPECT_NEAR(near.z / near.w, 0.0f, kEps);
}

// glTF cameras carry an aspectRatio (or xmag) for the shape they were authored
// at; an output of another shape must not stretch the image: the vertical
// extent is kept and the horizontal one follows the viewport.
TEST(Camera, ViewportAspectWinsOverTheCamerasOwn) {
  Camera camera;
  camera.yfov = std::numbers::pi_v<float> / 2;
  camera.aspectRatio = 1.0f;
  camera.znear = 1.0f;
  camera.zfar = 10.0f;
  const auto ndc = [&](float viewportAspect, glm::vec3 p) {
    const glm::vec4 clip = camera.projectionMatrix(viewportAspect) * glm::vec4(p, 1.0f);
    return glm::vec3(clip) / clip.w;
  };
  EXPECT_NEAR(ndc(2.0f, {0, 1, -1}).y, 1.0f, kEps) << "vertical field of view kept";
  EXPECT_NEAR(ndc(2.0f, {2, 0, -1}).x, 1.0f, kEps) << "width from the viewport, not aspectRatio 1";
  EXPECT_NEAR(ndc(0.5f, {0.5f, 0, -1}).x, 1.0f, kEps) << "narrower viewports too";

  camera.projection = Projection::Orthographic;
  camera.xmag = 1.0f;
  camera.ymag = 1.5f;
  EXPECT_NEAR(ndc(2.0f, {0, 1.5f, -5}).y, 1.0f, kEps) << "ymag kept";
  EXPECT_NEAR(ndc(2.0f, {3.0f, 0, -5}).x, 1.0f, kEps) << "half width ymag x aspect, not xmag";
}

}  // namespace
}  // namespace sg::scene
