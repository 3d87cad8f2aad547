// Object paths in scene files and the rigid motion they describe; the
// default scene's moving gold sphere.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/object_motion.hpp>
#include <shadelgraph/scene/scene_file.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

constexpr float kEps = 1e-4f;

std::filesystem::path writeTriangleScene(const TempDir& dir, const std::string& body) {
  std::filesystem::create_directories(dir.path() / "models");
  dir.write("models/triangle.bin", test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  dir.write("models/triangle.gltf", R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "tri", "mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "buffers": [{"uri": "triangle.bin", "byteLength": 36}]})");
  return dir.write("scene.json", body);
}

std::string loadError(const std::filesystem::path& file) {
  try {
    loadSceneFile(file);
  } catch (const SceneError& error) {
    return error.what();
  }
  ADD_FAILURE() << file << " loaded";
  return {};
}

glm::vec3 origin(const glm::mat4& world) { return glm::vec3(world[3]); }

TEST(ObjectMotion, OrbitStartsAtThePlacedPoseAndComesBack) {
  const ObjectMotion orbit{.type = ObjectMotion::Type::Orbit, .radius = 2.0f, .seconds = 4.0f};
  const glm::mat4 placed = glm::translate(glm::mat4(1.0f), {1, 2, 3});
  EXPECT_EQ(movedWorld(orbit, placed, 0.0f), placed) << "time 0 is exactly the placed pose";
  const glm::vec3 half = origin(movedWorld(orbit, placed, 2.0f));  // half a turn: 2 radii across
  EXPECT_NEAR(half.x, 1.0f - 4.0f, kEps);
  EXPECT_NEAR(half.y, 2.0f, kEps);
  EXPECT_NEAR(half.z, 3.0f, kEps);
  const glm::vec3 quarter = origin(movedWorld(orbit, placed, 1.0f));
  EXPECT_NEAR(quarter.x, 1.0f - 2.0f, kEps);
  EXPECT_NEAR(quarter.z, 3.0f + 2.0f, kEps);
  const glm::vec3 full = origin(movedWorld(orbit, placed, 4.0f));
  EXPECT_NEAR(glm::distance(full, glm::vec3(1, 2, 3)), 0.0f, kEps);
}

TEST(ObjectMotion, SpinTurnsAboutThePivotAndStaysRigid) {
  const ObjectMotion spin{.spinDegreesPerSecond = 90.0f, .pivot = {1, 0, 0}};
  const glm::mat4 placed = glm::translate(glm::mat4(1.0f), {2, 0, 0});
  const glm::mat4 moved = movedWorld(spin, placed, 1.0f);  // a quarter turn about y through (1, 0, 0)
  EXPECT_NEAR(origin(moved).x, 1.0f, kEps);
  EXPECT_NEAR(origin(moved).z, -1.0f, kEps);
  EXPECT_NEAR(glm::determinant(glm::mat3(moved)), 1.0f, kEps) << "rigid: no scale";
}

TEST(ObjectMotion, KeysPassThroughEveryKeyAndHoldAtTheEnds) {
  const ObjectMotion keys{.type = ObjectMotion::Type::Keys,
                          .keys = {{0.0f, {0, 0, 0}}, {1.0f, {1, 0, 0}}, {3.0f, {1, 2, 0}}}};
  const glm::mat4 placed(1.0f);
  for (const auto& key : keys.keys)
    EXPECT_NEAR(glm::distance(origin(movedWorld(keys, placed, key.time)), key.translation), 0.0f, kEps) << key.time;
  EXPECT_NEAR(glm::distance(origin(movedWorld(keys, placed, 10.0f)), glm::vec3(1, 2, 0)), 0.0f, kEps);
  EXPECT_NEAR(glm::distance(origin(movedWorld(keys, placed, -1.0f)), glm::vec3(0)), 0.0f, kEps);
}

TEST(ObjectMotion, SceneFileObjectsFollowTheirPath) {
  TempDir dir;
  const auto loaded = loadSceneFile(writeTriangleScene(dir, R"({"objects": [
    {"gltf": "models/triangle.gltf", "name": "mover", "translation": [5, 0, 0],
     "path": {"type": "orbit", "radius": 1, "seconds": 2, "spinDegreesPerSecond": 45}},
    {"gltf": "models/triangle.gltf", "name": "still"},
    {"gltf": "models/triangle.gltf", "name": "keyed",
     "path": {"type": "keys", "keys": [{"t": 0, "translation": [0, 0, 0]}, {"t": 1, "translation": [0, 3, 0]}]}}]})"));
  ASSERT_EQ(loaded.scene.instances.size(), 3u);
  const Instance& mover = loaded.scene.instances[0];
  EXPECT_EQ(mover.motion.type, ObjectMotion::Type::Orbit);
  EXPECT_FLOAT_EQ(mover.motion.radius, 1.0f);
  EXPECT_FLOAT_EQ(mover.motion.spinDegreesPerSecond, 45.0f);
  EXPECT_EQ(mover.motion.pivot, glm::vec3(5, 0, 0)) << "spins about the object's placed origin";
  EXPECT_FALSE(loaded.scene.instances[1].motion.moves());
  const Instance& keyed = loaded.scene.instances[2];
  EXPECT_NEAR(origin(movedWorld(keyed.motion, keyed.world, 1.0f)).y, 3.0f, kEps);
}

TEST(ObjectMotion, SceneFileErrorsNameThePath) {
  TempDir dir;
  const auto error = [&](const std::string& path) {
    return loadError(writeTriangleScene(dir, R"({"objects": [{"gltf": "models/triangle.gltf", "path": )" + path + "}]}"));
  };
  EXPECT_THAT(error(R"({"type": "orbit"})"), HasSubstr("/objects/0/path/radius: required property is missing"));
  EXPECT_THAT(error(R"({"type": "orbit", "radius": -1})"), HasSubstr("/objects/0/path/radius: must be > 0"));
  EXPECT_THAT(error(R"({"type": "fly"})"), HasSubstr("/objects/0/path/type"));
  EXPECT_THAT(error(R"({"type": "orbit", "radius": 1, "center": [0, 0, 0]})"), HasSubstr("unknown property 'center'"));
  EXPECT_THAT(error(R"({"type": "keys", "keys": []})"), HasSubstr("/objects/0/path/keys"));
  EXPECT_THAT(error(R"({"type": "keys", "keys": [{"t": 1, "translation": [0, 0, 0]}, {"t": 0, "translation": [0, 0, 0]}]})"),
              HasSubstr("/objects/0/path/keys/1/t: key times must increase strictly"));
  EXPECT_THAT(error(R"({"type": "spin"})"), HasSubstr("spinDegreesPerSecond: required property is missing"));
  EXPECT_THAT(error("[1]"), HasSubstr("/objects/0/path: expected an object"));
}

// The default scene's gold sphere moves (every multi-frame run sees object
// motion) and nothing else does; at time 0 it is where it was placed.
TEST(ObjectMotion, DefaultSceneMovesTheGoldSphereOnly) {
  const Scene s = makeDefaultScene(16);
  int moving = 0;
  for (const Instance& instance : s.instances) {
    if (!instance.motion.moves()) continue;
    ++moving;
    EXPECT_EQ(instance.name, "gold sphere");
    EXPECT_EQ(movedWorld(instance.motion, instance.world, 0.0f), instance.world);
    EXPECT_GT(glm::distance(origin(movedWorld(instance.motion, instance.world, 1.0f / 30.0f)), origin(instance.world)),
              0.01f)
        << "it moves visibly from one frame (1/30 s) to the next";
  }
  EXPECT_EQ(moving, 1);
}

}  // namespace
}  // namespace sg::scene
