// Which primitives go decoupled and the reasons printed for the rest, over
// scenes built in code: each primitive of a mesh is judged alone (its own
// chart and shadel space), alpha-mask materials go decoupled, alpha-blended
// ones stay forward naming the material.
#include <gtest/gtest.h>

#include <decoupled/shading_choice.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>
#include <shadelgraph/scene/uv_chart.hpp>

namespace sg::plugins {
namespace {

// A plane whose UVs cover [0,1]² (one quad per cell).
scene::Primitive plane(int material) {
  scene::Primitive p = scene::makePlane(1.0f, 1.0f, 2);
  p.material = material;
  return p;
}

struct SceneBuilder {
  scene::Scene scene;
  int material(std::string name, scene::AlphaMode mode) {
    scene::Material m;
    m.name = std::move(name);
    m.alphaMode = mode;
    scene.materials.push_back(m);
    return int(scene.materials.size()) - 1;
  }
  void object(std::vector<scene::Primitive> primitives, scene::ShadingMode mode) {
    scene::Mesh mesh{.name = "mesh " + std::to_string(scene.meshes.size()), .primitives = std::move(primitives)};
    for (const auto& p : mesh.primitives) mesh.bounds.extend(p.bounds);
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({.mesh = int(scene.meshes.size()) - 1, .name = "object", .shading = mode});
  }
};

TEST(ShadingChoice, EachPrimitiveIsJudgedAloneSoOverlappingPrimitivesGoDecoupled) {
  SceneBuilder b;
  const int a = b.material("a", scene::AlphaMode::Opaque), c = b.material("c", scene::AlphaMode::Opaque);
  b.object({plane(a), plane(c)}, scene::ShadingMode::Auto);
  // Together the two primitives' UVs overlap everywhere: no unique chart for the mesh.
  ASSERT_FALSE(scene::chooseShadingChart(b.scene.meshes[0]).unique);
  const auto choices = chooseShading(b.scene, std::nullopt);
  ASSERT_EQ(choices.size(), 1u);
  EXPECT_TRUE(choices[0].eligible);
  EXPECT_TRUE(choices[0].decoupled);
  ASSERT_EQ(choices[0].primitives.size(), 2u);
  for (const auto& p : choices[0].primitives) {
    EXPECT_TRUE(p.eligible);
    EXPECT_EQ(p.uvSet, 0);
  }
  EXPECT_EQ(choices[0].primitives[0].reason, choices[0].primitives[1].reason);
  EXPECT_EQ(choices[0].reason, "2 primitives, each: " + choices[0].primitives[0].reason);
}

TEST(ShadingChoice, AlphaMaskGoesDecoupledAlphaBlendStaysForwardWithItsReason) {
  SceneBuilder b;
  const int mask = b.material("leaves", scene::AlphaMode::Mask), blend = b.material("glass", scene::AlphaMode::Blend);
  b.object({plane(mask)}, scene::ShadingMode::Decoupled);
  b.object({plane(blend)}, scene::ShadingMode::Decoupled);
  const auto choices = chooseShading(b.scene, std::nullopt);
  ASSERT_EQ(choices.size(), 2u);
  EXPECT_TRUE(choices[0].decoupled) << choices[0].reason;
  EXPECT_NE(choices[0].reason.find("TEXCOORD_0"), std::string::npos) << choices[0].reason;
  EXPECT_FALSE(choices[1].eligible);
  EXPECT_FALSE(choices[1].decoupled);
  EXPECT_EQ(choices[1].reason, "alpha-blended material 'glass' (what is behind shows through: shaded forward)");
}

TEST(ShadingChoice, ABlendedPrimitiveStaysForwardWhileItsMeshGoesDecoupled) {
  SceneBuilder b;
  const int opaque = b.material("paint", scene::AlphaMode::Opaque), blend = b.material("glass", scene::AlphaMode::Blend);
  b.object({plane(opaque), plane(blend)}, scene::ShadingMode::Auto);
  const auto choices = chooseShading(b.scene, std::nullopt);
  EXPECT_TRUE(choices[0].decoupled);
  EXPECT_TRUE(choices[0].primitives[0].eligible);
  EXPECT_FALSE(choices[0].primitives[1].eligible);
  EXPECT_EQ(choices[0].reason, "primitive 0: " + choices[0].primitives[0].reason +
                                    "; primitive 1: alpha-blended material 'glass' (what is behind shows "
                                    "through: shaded forward)");
}

TEST(ShadingChoice, APrimitiveWithoutAChartKeepsItsObjectForwardInAutoMode) {
  SceneBuilder b;
  const int m = b.material("m", scene::AlphaMode::Opaque);
  scene::Primitive bare = plane(m);
  bare.uv0.clear();
  b.object({plane(m), bare}, scene::ShadingMode::Auto);
  const auto choices = chooseShading(b.scene, std::nullopt);
  EXPECT_FALSE(choices[0].eligible);
  EXPECT_FALSE(choices[0].decoupled);
  EXPECT_TRUE(choices[0].primitives[0].eligible);
  EXPECT_FALSE(choices[0].primitives[1].eligible);
  EXPECT_NE(choices[0].reason.find("primitive 1: no unique chart"), std::string::npos) << choices[0].reason;
}

TEST(ShadingChoice, DecoupledModeChartsEachPrimitiveWithoutAChart) {
  SceneBuilder b;
  const int m = b.material("m", scene::AlphaMode::Opaque);
  scene::Primitive bare = plane(m);
  bare.uv0.clear();
  b.object({plane(m), bare}, scene::ShadingMode::Auto);
  const auto choices = chooseShading(b.scene, scene::ShadingMode::Decoupled);
  EXPECT_TRUE(choices[0].decoupled) << choices[0].reason;
  ASSERT_EQ(b.scene.meshes[0].primitives.size(), 2u);
  EXPECT_FALSE(b.scene.meshes[0].primitives[1].uv1.empty()) << "the automatic chart is written to uv1";
  EXPECT_EQ(choices[0].primitives[1].uvSet, 1);
  EXPECT_NE(choices[0].primitives[1].reason.find("automatic chart"), std::string::npos);
  // Only the charted primitive is shaded in a chart of its own (its level rule, kResampledTextureLevelRule).
  EXPECT_FALSE(choices[0].primitives[0].automaticChart);
  EXPECT_TRUE(choices[0].primitives[1].automaticChart);
  // Choosing again on the same scene (the viewer does) finds the chart in uv1 and still knows it is automatic.
  const auto again = chooseShading(b.scene, scene::ShadingMode::Decoupled);
  EXPECT_FALSE(again[0].primitives[0].automaticChart);
  EXPECT_TRUE(again[0].primitives[1].automaticChart);
}

TEST(ShadingChoice, ForwardByRequestSaysSo) {
  SceneBuilder b;
  const int m = b.material("m", scene::AlphaMode::Mask);
  b.object({plane(m), plane(m)}, scene::ShadingMode::Forward);
  const auto choices = chooseShading(b.scene, std::nullopt);
  EXPECT_TRUE(choices[0].eligible);
  EXPECT_FALSE(choices[0].decoupled);
  EXPECT_EQ(choices[0].reason, "forward by request");
}

}  // namespace
}  // namespace sg::plugins
