// glTF animations: keyframe sampling (STEP, LINEAR, CUBICSPLINE, slerp),
// posing the node hierarchy, the loader's checks, and the sample models.
#include <array>
#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <shadelgraph/scene/animation.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/pose.hpp>
#include <shadelgraph/scene/scene_error.hpp>
#include <shadelgraph/scene/scene_file.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using Json = nlohmann::json;
using ::testing::HasSubstr;

float at(const AnimationSampler& s, float t) {
  std::array<float, 1> out{};
  sampleAt(s, t, false, out);
  return out[0];
}

TEST(AnimationSampling, StepHoldsTheKeyBefore) {
  const AnimationSampler s{{0, 1, 2}, {0, 10, 20}, 1, Interpolation::Step};
  EXPECT_EQ(at(s, 0.5f), 0.0f);
  EXPECT_EQ(at(s, 1.0f), 10.0f);
  EXPECT_EQ(at(s, 1.99f), 10.0f);
}

TEST(AnimationSampling, LinearInterpolatesAndClampsAtTheEnds) {
  const AnimationSampler s{{1, 2, 4}, {0, 10, 30}, 1, Interpolation::Linear};
  EXPECT_FLOAT_EQ(at(s, 1.25f), 2.5f);
  EXPECT_FLOAT_EQ(at(s, 3.0f), 20.0f);
  EXPECT_EQ(at(s, -5.0f), 0.0f) << "before the first key";
  EXPECT_EQ(at(s, 9.0f), 30.0f) << "after the last key";
  const AnimationSampler single{{3}, {7}, 1, Interpolation::Linear};
  EXPECT_EQ(at(single, 0.0f), 7.0f);
  EXPECT_EQ(at(single, 5.0f), 7.0f);
}

// Keys on p(t) = t^3 with its derivative 3t^2 as both tangents: the glTF
// Hermite spline (tangents scaled by the key interval) reproduces the cubic.
TEST(AnimationSampling, CubicSplineReproducesACubic) {
  const std::vector<float> times{0, 1, 2.5f};
  std::vector<float> values;
  for (const float t : times) values.insert(values.end(), {3 * t * t, t * t * t, 3 * t * t});  // in, value, out
  const AnimationSampler s{times, values, 1, Interpolation::CubicSpline};
  for (const float t : {0.0f, 0.3f, 0.5f, 1.0f, 1.7f, 2.2f, 2.5f}) EXPECT_NEAR(at(s, t), t * t * t, 1e-4f) << t;
}

glm::quat rotationAt(const AnimationSampler& s, float t) {
  std::array<float, 4> q{};
  sampleAt(s, t, true, q);
  return {q[3], q[0], q[1], q[2]};
}

TEST(AnimationSampling, LinearRotationsSlerpAlongTheShorterArc) {
  const glm::quat quarter = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
  for (const float sign : {1.0f, -1.0f}) {  // -q is the same rotation; the far way round would pass 180 degrees
    const glm::quat end = quarter * sign;
    const AnimationSampler s{{0, 1}, {0, 0, 0, 1, end.x, end.y, end.z, end.w}, 4, Interpolation::Linear};
    const glm::quat half = rotationAt(s, 0.5f);
    const glm::quat expected = glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 0, 1));
    EXPECT_NEAR(std::abs(glm::dot(half, expected)), 1.0f, 1e-6f) << "sign " << sign;
    EXPECT_NEAR(glm::length(half), 1.0f, 1e-6f);
  }
}

TEST(AnimationSampling, RotationsComeOutUnitLength) {
  // Cubic splines between unit keys leave the sphere; a zero key has no direction.
  const AnimationSampler cubic{{0, 1}, {0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0}, 4,
                               Interpolation::CubicSpline};
  EXPECT_NEAR(glm::length(rotationAt(cubic, 0.5f)), 1.0f, 1e-6f);
  const AnimationSampler zero{{0}, {0, 0, 0, 0}, 4, Interpolation::Step};
  EXPECT_EQ(rotationAt(zero, 0.0f), glm::quat(1, 0, 0, 0)) << "no rotation rather than NaN";
}

// A triangle on node 1 (child of node 0, at x = 10); node 1 is animated.
struct AnimatedFile {
  test::TempDir dir;
  Json document = Json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"translation": [10, 0, 0], "children": [1]}, {"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "animations": [{"name": "slide", "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}],
                    "samplers": [{"input": 1, "output": 2}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [2]},
                  {"bufferView": 2, "componentType": 5126, "count": 2, "type": "VEC3"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8},
                    {"buffer": 0, "byteOffset": 44, "byteLength": 24}],
    "buffers": [{"uri": "animated.bin", "byteLength": 68}]})");
  std::vector<float> times{0, 2};

  std::filesystem::path write() {
    dir.write("animated.bin", test::concat({test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                           test::bytesOf(times), test::bytesOf(std::vector<float>{0, 0, 0, 0, 4, 0})}));
    return dir.write("animated.gltf", document.dump());
  }
};

TEST(AnimationLoading, PosesTheHierarchyAtATime) {
  AnimatedFile file;
  Scene scene = loadGltf(file.write());
  ASSERT_EQ(scene.animations.size(), 1u);
  EXPECT_EQ(scene.animations[0].name, "slide");
  EXPECT_EQ(scene.animations[0].duration(), 2.0f);
  ASSERT_EQ(scene.nodes.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_EQ(scene.nodes[static_cast<size_t>(scene.instances[0].node)].parent, 0);
  const std::vector<int> all = allAnimations(scene);
  applyPose(scene, poseNodes(scene, all, 0.5f));
  EXPECT_EQ(glm::vec3(scene.instances[0].world[3]), glm::vec3(10, 1, 0)) << "the parent's x plus a quarter of the slide";
  applyPose(scene, poseNodes(scene, {}, 0.5f));
  EXPECT_EQ(glm::vec3(scene.instances[0].world[3]), glm::vec3(10, 0, 0)) << "no animation: the rest pose";
}

// Three objects place the file of AnimatedFile: each gets its own nodes, and
// the animation it chooses runs on its own clock.
TEST(SceneFileAnimation, EachObjectAnimatesOnItsOwnClock) {
  AnimatedFile file;
  file.write();
  const auto scenePath = file.dir.write("scene.json", R"({"objects": [
    {"gltf": "animated.gltf", "name": "a"},
    {"gltf": "animated.gltf", "name": "b", "translation": [0, 0, 5], "animation": "slide", "timeOffset": 1},
    {"gltf": "animated.gltf", "name": "c", "translation": [0, 0, 9], "animation": "none"}]})");
  Scene scene = loadSceneFile(scenePath).scene;
  ASSERT_EQ(scene.animations.size(), 2u);
  EXPECT_EQ(scene.animations[0].name, "a/slide");
  EXPECT_EQ(scene.animations[1].name, "b/slide");
  EXPECT_EQ(scene.animations[1].timeOffset, 1.0f);
  ASSERT_EQ(scene.nodes.size(), 6u) << "a copy of the file's two nodes per object";
  ASSERT_EQ(scene.instances.size(), 3u);
  applyPose(scene, poseNodes(scene, allAnimations(scene), 0.5f));
  EXPECT_EQ(glm::vec3(scene.instances[0].world[3]), glm::vec3(10, 1, 0)) << "a: a quarter of the slide";
  EXPECT_EQ(glm::vec3(scene.instances[1].world[3]), glm::vec3(10, 3, 5)) << "b: 1.5 s into it, where it was placed";
  EXPECT_EQ(glm::vec3(scene.instances[2].world[3]), glm::vec3(10, 0, 9)) << "c: no animation, the rest pose";
}

TEST(SceneFileAnimation, EachObjectSkinsWithItsOwnJoints) {
  SG_REQUIRE_ASSETS();
  test::TempDir dir;
  const std::string model = test::samplePath("RiggedSimple").string();
  const auto scenePath = dir.write("scene.json", R"({"objects": [{"gltf": ")" + model + R"(", "name": "a"},
    {"gltf": ")" + model + R"(", "name": "b", "translation": [3, 0, 0], "timeOffset": 0.5}]})");
  const Scene scene = loadSceneFile(scenePath, LoadOptions{.decodeImages = false}).scene;
  ASSERT_EQ(scene.skins.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 2u);
  const size_t nodesPerObject = scene.nodes.size() / 2;
  EXPECT_EQ(scene.instances[0].skin, 0);
  EXPECT_EQ(scene.instances[1].skin, 1);
  ASSERT_EQ(scene.skins[0].joints.size(), scene.skins[1].joints.size());
  for (size_t j = 0; j < scene.skins[0].joints.size(); ++j)
    EXPECT_EQ(size_t(scene.skins[1].joints[j]), size_t(scene.skins[0].joints[j]) + nodesPerObject)
        << "b's skin moves with b's own copy of the joints";
}

TEST(SceneFileAnimation, AnUnknownChoiceNamesTheAnimationsThereAre) {
  AnimatedFile file;
  file.write();
  for (const char* choice : {R"("walk")", "3", "true"}) {
    const auto scenePath =
        file.dir.write("scene.json", std::string(R"({"objects": [{"gltf": "animated.gltf", "animation": )") + choice + "}]}");
    try {
      loadSceneFile(scenePath);
      ADD_FAILURE() << choice << " was accepted";
    } catch (const SceneError& error) {
      EXPECT_THAT(error.what(), HasSubstr("/objects/0/animation")) << choice;
      EXPECT_THAT(error.what(), HasSubstr("0 'slide'")) << choice;
    }
  }
}

TEST(AnimationLoading, KeyTimesMustIncrease) {
  AnimatedFile file;
  file.times = {1, 1};
  EXPECT_THAT([&] { loadGltf(file.write()); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr(
                  "animation 0 'slide' sampler 0: keyframe times must increase strictly; time 1 (1.000000) follows 1.000000")));
}

TEST(AnimationLoading, OutputCountMustMatchTheKeys) {
  AnimatedFile file;
  file.document["animations"][0]["samplers"][0]["interpolation"] = "CUBICSPLINE";
  EXPECT_THAT([&] { loadGltf(file.write()); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr(
                  "sampler 0: output has 2 elements for 2 keyframes (CUBICSPLINE: 3 per keyframe)")));
}

TEST(AnimationLoading, UnknownInterpolationIsNamed) {
  AnimatedFile file;
  file.document["animations"][0]["samplers"][0]["interpolation"] = "BOUNCE";
  EXPECT_THAT([&] { loadGltf(file.write()); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("interpolation 'BOUNCE' is not LINEAR, STEP or CUBICSPLINE")));
}

TEST(AnimationLoading, WrongOutputTypeIsNamed) {
  AnimatedFile file;
  file.document["animations"][0]["channels"][0]["target"]["path"] = "rotation";
  EXPECT_THAT([&] { loadGltf(file.write()); },
              ::testing::ThrowsMessage<SceneError>(HasSubstr("sampler 0: output is VEC3, its channel needs VEC4")));
}

TEST(AnimationLoading, ChannelsGlTFForbidsAreSkippedWithAWarning) {
  AnimatedFile file;
  file.document["nodes"][1]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const Scene matrix = loadGltf(file.write());
  EXPECT_TRUE(matrix.animations.at(0).channels.empty());
  EXPECT_THAT(matrix.warnings, ::testing::Contains(HasSubstr("has a matrix, which glTF forbids animating")));

  AnimatedFile pointer;
  pointer.document["animations"][0]["channels"][0]["target"]["path"] = "pointer";
  const Scene skipped = loadGltf(pointer.write());
  EXPECT_TRUE(skipped.animations.at(0).channels.empty());
  EXPECT_THAT(skipped.warnings, ::testing::Contains(HasSubstr("target path 'pointer' is not supported; skipped")));
}

// InterpolationTest: nine cubes, one animation each, every path with every
// interpolation; each cube is a root node, so its world transform is the
// animated local one.
TEST(AnimationAssets, InterpolationTestHitsEveryKey) {
  SG_REQUIRE_ASSETS();
  const Scene rest = loadGltf(test::samplePath("InterpolationTest"), LoadOptions{.decodeImages = false});
  ASSERT_EQ(rest.animations.size(), 9u);
  int interpolations[3] = {};
  for (size_t a = 0; a < rest.animations.size(); ++a) {
    const Animation& animation = rest.animations[a];
    ASSERT_EQ(animation.channels.size(), 1u) << animation.name;
    const AnimationChannel& channel = animation.channels[0];
    const AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
    ++interpolations[static_cast<int>(sampler.interpolation)];
    const int only[] = {static_cast<int>(a)};
    for (size_t k = 0; k < sampler.times.size(); ++k) {
      const std::vector<glm::mat4> world = poseNodes(rest, only, sampler.times[k]);
      const glm::mat4& m = world[static_cast<size_t>(channel.node)];
      const size_t groups = sampler.interpolation == Interpolation::CubicSpline ? 3 : 1;
      const float* key = sampler.values.data() + (k * groups + groups / 2) * sampler.width;
      if (channel.path == AnimatedPath::Translation) {
        EXPECT_NEAR(glm::distance(glm::vec3(m[3]), glm::vec3(key[0], key[1], key[2])), 0.0f, 1e-5f) << animation.name << k;
      } else if (channel.path == AnimatedPath::Scale) {
        const glm::vec3 scale(glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2])));
        EXPECT_NEAR(glm::distance(scale, glm::abs(glm::vec3(key[0], key[1], key[2]))), 0.0f, 1e-4f) << animation.name << k;
      } else {
        const glm::quat q = glm::normalize(glm::quat(key[3], key[0], key[1], key[2]));
        EXPECT_NEAR(std::abs(glm::dot(glm::quat_cast(glm::mat3(m)), q)), 1.0f, 1e-4f) << animation.name << k;
      }
    }
    // Halfway between the first two keys: STEP still holds the first.
    if (sampler.interpolation == Interpolation::Step && sampler.times.size() > 1) {
      const float mid = 0.5f * (sampler.times[0] + sampler.times[1]);
      EXPECT_EQ(poseNodes(rest, only, mid)[static_cast<size_t>(channel.node)],
                poseNodes(rest, only, sampler.times[0])[static_cast<size_t>(channel.node)]) << animation.name;
    }
  }
  EXPECT_EQ(interpolations[0], 3);
  EXPECT_EQ(interpolations[1], 3);
  EXPECT_EQ(interpolations[2], 3);
}

TEST(AnimationAssets, BoxAnimatedMovesItsBoxesOverTime) {
  SG_REQUIRE_ASSETS();
  Scene scene = loadGltf(test::samplePath("BoxAnimated"), LoadOptions{.decodeImages = false});
  ASSERT_EQ(scene.animations.size(), 1u);
  EXPECT_EQ(scene.animations[0].channels.size(), 2u);
  const float duration = scene.animations[0].duration();
  EXPECT_GT(duration, 0.0f);
  const std::vector<int> all = allAnimations(scene);
  std::vector<std::vector<glm::mat4>> worlds;
  for (const float t : {0.0f, duration * 0.3f, duration * 0.6f}) {
    applyPose(scene, poseNodes(scene, all, t));
    worlds.emplace_back();
    for (const Instance& instance : scene.instances) worlds.back().push_back(instance.world);
  }
  // The inner box hangs off a translated node and is itself rotated; the outer one is a root nothing drives.
  ASSERT_EQ(scene.instances.size(), 2u);
  size_t moved = 0, still = 0;
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    moved += worlds[0][i] != worlds[1][i] && worlds[1][i] != worlds[2][i];
    still += worlds[0][i] == worlds[1][i] && worlds[1][i] == worlds[2][i];
  }
  EXPECT_EQ(moved, 1u);
  EXPECT_EQ(still, 1u);
}

}  // namespace
}  // namespace sg::scene
