// The per-frame layer plan over plain data: passes per stack depth, one
// dispatch per object per layer, images and history only where needed.
#include <gtest/gtest.h>

#include <builtin_materials.hpp>
#include <decoupled/layer_plan.hpp>

namespace sg::plugins {
namespace {

class LayerPlanTest : public ::testing::Test {
 protected:
  LayerPlanTest() { materials::registerBuiltinMaterials(registry_); }
  LayerPlan plan(std::vector<uint32_t> objects, std::vector<std::string> materials) {
    return planLayers(registry_, objects, materials);
  }
  plugin::Registry registry_;
};

TEST_F(LayerPlanTest, NoObjectsNoPasses) {
  const auto p = plan({}, {});
  EXPECT_TRUE(p.depths.empty());
  EXPECT_EQ(p.dispatches, 0u);
  EXPECT_FALSE(p.needsSupport);
}

TEST_F(LayerPlanTest, OneLayerMaterialsShareOneStep) {
  const auto p = plan({0, 3, 7}, {"gltf-pbr", "gltf-pbr", "gltf-pbr"});
  ASSERT_EQ(p.depths.size(), 1u);
  ASSERT_EQ(p.depths[0].size(), 1u);
  EXPECT_EQ(p.depths[0][0].layer, "gltf-pbr");
  EXPECT_TRUE(p.depths[0][0].final);
  EXPECT_EQ(p.depths[0][0].objects, (std::vector<uint32_t>{0, 3, 7}));
  EXPECT_EQ(p.dispatches, 3u);
  EXPECT_TRUE(p.images.empty());
  EXPECT_TRUE(p.persistent.empty());
}

TEST_F(LayerPlanTest, MixedStacksGetAPassPerDepth) {
  const auto p = plan({1, 2, 5}, {"skin", "gltf-pbr", "marble"});
  ASSERT_EQ(p.depths.size(), 3u);
  // Depth 0: gltf-pbr as skin's intermediate and as a final layer are two steps.
  ASSERT_EQ(p.depths[0].size(), 3u);
  EXPECT_EQ(p.depths[0][0].layer, "gltf-pbr");
  EXPECT_FALSE(p.depths[0][0].final);
  EXPECT_EQ(p.depths[0][1].layer, "gltf-pbr");
  EXPECT_TRUE(p.depths[0][1].final);
  EXPECT_EQ(p.depths[0][2].layer, "marble");
  EXPECT_EQ(p.depths[2].size(), 1u);
  EXPECT_EQ(p.depths[2][0].layer, "blur-v");
  EXPECT_EQ(p.dispatches, 3u + 1u + 2u);
  EXPECT_EQ(p.images, (std::vector<std::string>{"gltf-pbr", "blur-u", "marble"}));
  EXPECT_EQ(p.persistent, std::vector<std::string>{"marble"});
  EXPECT_TRUE(p.needsSupport);
}

TEST_F(LayerPlanTest, SupportOnlyForNeighbourhoodReads) {
  EXPECT_FALSE(plan({0}, {"marble"}).needsSupport);
  EXPECT_TRUE(plan({0}, {"bumps"}).needsSupport);
  EXPECT_EQ(supportRadius(registry_, registry_.material("skin")), 4u);
  EXPECT_EQ(supportRadius(registry_, registry_.material("gltf-pbr")), 0u);
}

TEST_F(LayerPlanTest, TooManyPersistentLayersIsAClearError) {
  for (int i = 0; i < 9; ++i) {
    const std::string name = "cache" + std::to_string(i);
    registry_.addLayer({.name = name, .source = "c.glsl", .function = "c", .persistent = true});
    registry_.addMaterial({.name = name, .layers = {name, "gltf-pbr"}});
  }
  std::vector<uint32_t> objects;
  std::vector<std::string> materials;
  for (uint32_t i = 0; i < 9; ++i) {
    objects.push_back(i);
    materials.push_back("cache" + std::to_string(i));
  }
  EXPECT_THROW(plan(objects, materials), plugin::PluginError);
}

}  // namespace
}  // namespace sg::plugins
