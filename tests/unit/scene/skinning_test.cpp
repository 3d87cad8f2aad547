// Skins and morph targets: what the loader reads (JOINTS_0/1, WEIGHTS_0/1,
// inverse bind matrices, target deltas, default and animated weights), the
// CPU reference of the GPU skinning pass, and the conservative bounds culling uses.
#include <algorithm>
#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <shadelgraph/scene/deformation.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/pose.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using Json = nlohmann::json;
using ::testing::HasSubstr;

// A triangle skinned to two joints (joint 1 at x = 5) with eight influences a
// vertex (JOINTS_1) and one morph target moving it +z, at weight 0.5.
struct SkinnedFile {
  test::TempDir dir;
  Json document = Json::parse(R"({
    "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
    "nodes": [{"mesh": 0, "skin": 0}, {"name": "root"}, {"name": "arm", "translation": [5, 0, 0]}],
    "skins": [{"joints": [1, 2], "inverseBindMatrices": 5}],
    "meshes": [{"weights": [0.5], "primitives": [{"attributes": {"POSITION": 0, "JOINTS_0": 1, "WEIGHTS_0": 2,
                                                                 "JOINTS_1": 3, "WEIGHTS_1": 4},
                                                  "targets": [{"POSITION": 6}]}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5121, "count": 3, "type": "VEC4"},
                  {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC4"},
                  {"bufferView": 3, "componentType": 5121, "count": 3, "type": "VEC4"},
                  {"bufferView": 4, "componentType": 5126, "count": 3, "type": "VEC4"},
                  {"bufferView": 5, "componentType": 5126, "count": 2, "type": "MAT4"},
                  {"bufferView": 6, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 12},
                    {"buffer": 0, "byteOffset": 48, "byteLength": 48}, {"buffer": 0, "byteOffset": 96, "byteLength": 12},
                    {"buffer": 0, "byteOffset": 108, "byteLength": 48}, {"buffer": 0, "byteOffset": 156, "byteLength": 128},
                    {"buffer": 0, "byteOffset": 284, "byteLength": 36}],
    "buffers": [{"uri": "skinned.bin", "byteLength": 320}]})");
  std::vector<uint8_t> joints0{0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};

  std::filesystem::path write() {
    const std::vector<float> identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    std::vector<float> inverseBind = identity;
    inverseBind.insert(inverseBind.end(), identity.begin(), identity.end());
    dir.write("skinned.bin",
              test::concat({test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}), joints0,
                            // vertex 0 all on joint 0; vertex 1 half on joint 1 (set 0), half on joint 0 (set 1);
                            // vertex 2 on joint 1 with weight 2 (normalized to 1).
                            test::bytesOf(std::vector<float>{1, 0, 0, 0, 0.5f, 0, 0, 0, 2, 0, 0, 0}),
                            std::vector<uint8_t>(12, 0),
                            test::bytesOf(std::vector<float>{0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 0, 0, 0}),
                            test::bytesOf(inverseBind), test::bytesOf(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1})}));
    return dir.write("skinned.gltf", document.dump());
  }
};

TEST(SkinLoading, ReadsJointsWeightsInverseBindMatricesAndTargets) {
  SkinnedFile file;
  const Scene scene = loadGltf(file.write());
  ASSERT_EQ(scene.skins.size(), 1u);
  EXPECT_EQ(scene.skins[0].joints.size(), 2u);
  EXPECT_EQ(scene.skins[0].inverseBindMatrices[1], glm::mat4(1.0f));
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_EQ(scene.instances[0].skin, 0);
  EXPECT_EQ(scene.instances[0].morphWeights, std::vector<float>{0.5f}) << "the mesh's default weights";
  const Primitive& p = scene.meshes[0].primitives[0];
  ASSERT_EQ(p.joints0.size(), 3u);
  ASSERT_EQ(p.joints1.size(), 3u) << "JOINTS_1: eight influences";
  EXPECT_EQ(p.joints0[1], glm::uvec4(1, 0, 0, 0));
  EXPECT_EQ(p.weights0[2], glm::vec4(1, 0, 0, 0)) << "weight 2 normalized to 1";
  EXPECT_EQ(p.weights0[1].x + p.weights1[1].x, 1.0f);
  ASSERT_EQ(p.targets.size(), 1u);
  EXPECT_EQ(p.targets[0].positions[0], glm::vec3(0, 0, 1));
  EXPECT_TRUE(scene.meshes[0].deformable());
  EXPECT_THAT(scene.warnings, ::testing::Contains(HasSubstr("WEIGHTS did not sum to 1; normalized")));
  for (const std::string& warning : scene.warnings) {
    EXPECT_THAT(warning, ::testing::Not(HasSubstr("not supported")));
    EXPECT_THAT(warning, ::testing::Not(HasSubstr("ignored")));
  }
}

TEST(SkinLoading, DeformsLikeTheHandComputedPose) {
  SkinnedFile file;
  const Scene scene = loadGltf(file.write());
  const Primitive& p = scene.meshes[0].primitives[0];
  const std::vector<glm::mat4> joints = jointWorldMatrices(scene.skins[0], poseNodes(scene, {}, 0.0f));
  const std::vector<float> weights = scene.instances[0].morphWeights;
  // Morph first (+0.5 z), then skin: joint 1 sits 5 along x, joint 0 at the origin.
  EXPECT_EQ(deformVertex(p, 0, joints, weights).position, glm::vec3(0, 0, 0.5f));
  EXPECT_EQ(deformVertex(p, 1, joints, weights).position, glm::vec3(3.5f, 0, 0.5f)) << "half on each joint";
  EXPECT_EQ(deformVertex(p, 2, joints, weights).position, glm::vec3(5, 1, 0.5f));
  EXPECT_EQ(deformVertex(p, 2, joints, std::vector<float>{0.0f}).position, glm::vec3(5, 1, 0)) << "weight 0: no delta";
  const Bounds bounds = deformedBounds(deformationBounds(scene.meshes[0]), joints, weights);
  EXPECT_EQ(bounds.min, glm::vec3(0, 0, 0.5f));
  EXPECT_EQ(bounds.max, glm::vec3(6, 1, 0.5f)) << "joint 1's box (vertices 1, 2) moved +5: conservative for vertex 1";
}

TEST(SkinLoading, JointsBeyondTheSkinAreNamed) {
  SkinnedFile file;
  file.joints0[0] = 2;
  try {
    loadGltf(file.write());
    FAIL() << "expected an error";
  } catch (const SceneError& error) {
    EXPECT_THAT(error.what(), HasSubstr("JOINTS name joint 2, its skin has 2"));
  }
}

TEST(SkinLoading, InverseBindMatricesMustBeMat4) {
  SkinnedFile file;
  file.document["accessors"][5]["type"] = "VEC4";
  file.document["accessors"][5]["count"] = 8;
  try {
    loadGltf(file.write());
    FAIL() << "expected an error";
  } catch (const SceneError& error) {
    EXPECT_THAT(error.what(), HasSubstr("inverseBindMatrices must be MAT4 of FLOAT"));
  }
}

TEST(SkinLoading, NodeWeightsMustMatchTheTargets) {
  SkinnedFile file;
  file.document["nodes"][0]["weights"] = Json::array({0.1, 0.2});
  try {
    loadGltf(file.write());
    FAIL() << "expected an error";
  } catch (const SceneError& error) {
    EXPECT_THAT(error.what(), HasSubstr("2 weights for its mesh's 1 morph targets"));
  }
}

TEST(SkinAssets, RiggedSimpleHasItsSkin) {
  SG_REQUIRE_ASSETS();
  const Scene scene = loadGltf(test::samplePath("RiggedSimple"), LoadOptions{.decodeImages = false});
  ASSERT_EQ(scene.skins.size(), 1u);
  EXPECT_EQ(scene.skins[0].joints.size(), 2u);
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_EQ(scene.instances[0].skin, 0);
  const Primitive& p = scene.meshes[0].primitives[0];
  ASSERT_EQ(p.joints0.size(), p.vertexCount());
  for (size_t v = 0; v < p.vertexCount(); ++v) {
    const glm::vec4 w = p.weights0[v];
    EXPECT_NEAR(w.x + w.y + w.z + w.w, 1.0f, 1e-5f) << "vertex " << v;
  }
  // At rest (the bind pose of this file) skinning leaves the vertices where they are.
  const std::vector<glm::mat4> joints = jointWorldMatrices(scene.skins[0], poseNodes(scene, {}, 0.0f));
  const glm::mat4 toMesh = glm::inverse(scene.instances[0].world);
  std::vector<glm::mat4> meshJoints;
  for (const glm::mat4& j : joints) meshJoints.push_back(toMesh * j);
  for (size_t v = 0; v < p.vertexCount(); v += 7) {
    const glm::vec3 d = deformVertex(p, v, meshJoints, {}).position - p.positions[v];
    EXPECT_LT(glm::length(d), 1e-3f) << "vertex " << v;
  }
}

// Every deformed vertex lies in the deformed bounds, at every sampled time of the animation.
void expectBoundsHold(const char* model) {
  const Scene scene = loadGltf(test::samplePath(model), LoadOptions{.decodeImages = false});
  const std::vector<int> all = allAnimations(scene);
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[size_t(instance.mesh)];
    if (!mesh.deformable()) continue;
    const DeformationBounds rest = deformationBounds(mesh);
    for (float t : {0.0f, 0.4f, 0.9f, 1.7f}) {
      const std::vector<glm::mat4> world = poseNodes(scene, all, t);
      const std::vector<std::vector<float>> weights = poseWeights(scene, all, t);
      const glm::mat4 toMesh = glm::inverse(world[size_t(instance.node)]);
      std::vector<glm::mat4> joints;
      if (instance.skin >= 0)
        for (const glm::mat4& j : jointWorldMatrices(scene.skins[size_t(instance.skin)], world)) joints.push_back(toMesh * j);
      const std::vector<float>& w = weights[size_t(instance.node)];
      Bounds box = deformedBounds(rest, joints, w);
      const glm::vec3 slack(1e-3f * std::max(1.0f, glm::length(box.size())));
      box.min -= slack;
      box.max += slack;
      Bounds moved;
      for (const Primitive& p : mesh.primitives)
        for (size_t v = 0; v < p.vertexCount(); ++v) {
          const glm::vec3 q = deformVertex(p, v, joints, w).position;
          moved.extend(q);
          ASSERT_TRUE(glm::all(glm::greaterThanEqual(q, box.min)) && glm::all(glm::lessThanEqual(q, box.max)))
              << model << " t " << t << " vertex " << v;
        }
      if (t > 0.0f && instance.skin >= 0) {
        EXPECT_GT(glm::length(moved.center() - mesh.bounds.center()) + glm::length(moved.size() - mesh.bounds.size()), 1e-3f)
            << model << " t " << t << ": the pose moves the vertices";
      }
    }
  }
}

TEST(SkinAssets, DeformedBoundsHoldEveryVertex) {
  SG_REQUIRE_ASSETS();
  for (const char* model : {"RiggedSimple", "CesiumMan", "SimpleMorph", "AnimatedMorphCube"}) expectBoundsHold(model);
}

TEST(MorphAssets, SimpleMorphWeightsFollowTheAnimation) {
  SG_REQUIRE_ASSETS();
  Scene scene = loadGltf(test::samplePath("SimpleMorph"), LoadOptions{.decodeImages = false});
  ASSERT_EQ(scene.meshes[0].weights, (std::vector<float>{0.5f, 0.5f}));
  ASSERT_EQ(scene.meshes[0].primitives[0].targets.size(), 2u);
  ASSERT_EQ(scene.animations.size(), 1u);
  const AnimationSampler& sampler = scene.animations[0].samplers[0];
  ASSERT_EQ(sampler.width, 2u) << "one weight per target";
  ASSERT_GE(sampler.times.size(), 2u);
  const std::vector<int> all = allAnimations(scene);
  const int node = scene.instances[0].node;
  // At a key: the key's values; halfway between the first two (LINEAR): their mean.
  EXPECT_EQ(poseWeights(scene, all, sampler.times[1])[size_t(node)],
            (std::vector<float>{sampler.values[2], sampler.values[3]}));
  const float mid = 0.5f * (sampler.times[0] + sampler.times[1]);
  const std::vector<float> half = poseWeights(scene, all, mid)[size_t(node)];
  EXPECT_NEAR(half[0], 0.5f * (sampler.values[0] + sampler.values[2]), 1e-5f);
  EXPECT_NEAR(half[1], 0.5f * (sampler.values[1] + sampler.values[3]), 1e-5f);
  applyWeights(scene, poseWeights(scene, all, sampler.times[1]));
  EXPECT_EQ(scene.instances[0].morphWeights, (std::vector<float>{sampler.values[2], sampler.values[3]}));
  EXPECT_EQ(poseWeights(scene, {}, 1.0f)[size_t(node)], (std::vector<float>{0.5f, 0.5f})) << "no animation: the defaults";
}

}  // namespace
}  // namespace sg::scene
