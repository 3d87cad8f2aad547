// The CPU halves of per-layer rates and budget mode: which view-independent
// layers an object keeps (layer_rate.hpp) and the budget's age limit
// (shade_budget.hpp), over plain data.
#include <gtest/gtest.h>

#include <array>

#include <builtin_materials.hpp>
#include <decoupled/layer_rate.hpp>
#include <decoupled/shade_budget.hpp>

namespace sg::plugins {
namespace {

class LayerRateTest : public ::testing::Test {
 protected:
  LayerRateTest() { materials::registerBuiltinMaterials(registry_); }
  uint32_t bits(const std::string& material, const LayerKeepState& state) {
    return keptLayerBits(registry_, registry_.material(material), slots_, state);
  }
  plugin::Registry registry_;
  std::vector<std::string> slots_{"marble", "height", "diffuse-light"};
};

TEST_F(LayerRateTest, BuiltInLayersDeclareWhatTheyDependOn) {
  EXPECT_EQ(registry_.layer("diffuse-light").dependsOn, plugin::LayerDependence::World);
  EXPECT_EQ(registry_.layer("height").dependsOn, plugin::LayerDependence::Surface);
  for (const char* view : {"gltf-pbr", "specular-light", "normal-from-height", "blur-u", "marble-shade", "uv-checker"})
    EXPECT_EQ(registry_.layer(view).dependsOn, plugin::LayerDependence::View) << view;
}

TEST_F(LayerRateTest, KeptOnlyWhileTheInputsHold) {
  const LayerKeepState steady{.historyValid = true, .shadeFrame = true, .shadeFrameIndex = 3};
  EXPECT_EQ(bits("split-pbr", steady), 1u << 2) << "diffuse-light, slot 2";
  EXPECT_EQ(bits("bumps", steady), 1u << 1) << "height, slot 1";
  EXPECT_EQ(bits("gltf-pbr", steady), 0u) << "nothing view-independent";
  EXPECT_EQ(bits("marble", steady), 0u) << "persistent layers decide for themselves";

  auto state = steady;
  state.historyValid = false;
  EXPECT_EQ(bits("split-pbr", state), 0u);
  state = steady;
  state.materialChanged = true;
  EXPECT_EQ(bits("bumps", state), 0u);
  state = steady;
  state.moved = true;
  EXPECT_EQ(bits("split-pbr", state), 0u) << "diffuse light depends on the world pose";
  EXPECT_EQ(bits("bumps", state), 1u << 1) << "the height only on the surface";
}

TEST_F(LayerRateTest, RefreshedEveryEighthShadeFrame) {
  for (uint64_t index = 1; index <= 17; ++index) {
    const bool refresh = index % plugin::kDefaultRefreshShadeFrames == 0;
    EXPECT_EQ(bits("split-pbr", {.historyValid = true, .shadeFrame = true, .shadeFrameIndex = index}),
              refresh ? 0u : 1u << 2)
        << index;
    EXPECT_EQ(bits("split-pbr", {.historyValid = true, .shadeFrame = false, .shadeFrameIndex = index}), 1u << 2)
        << "frames between shade frames never refresh";
  }
}

std::array<uint32_t, 16> ages(std::initializer_list<std::pair<size_t, uint32_t>> counts) {
  std::array<uint32_t, 16> a{};
  for (const auto& [age, count] : counts) a[age] = count;
  return a;
}

TEST(ShadeBudgetTest, EverythingFitsEverythingIsReshaded) {
  const ShadeBudget budget(10.0, 0.01);  // 1000 chunks
  EXPECT_EQ(budget.budgetChunks(), 1000u);
  const auto limit = budget.nextAgeLimit(100, 100, ages({{1, 300}, {2, 200}}), {});
  EXPECT_EQ(limit.limit, 1u);
  EXPECT_EQ(limit.fraction, kWholeFraction);
}

TEST(ShadeBudgetTest, OldestFirstThenAFractionOfTheLimitAge) {
  const ShadeBudget budget(3.0, 0.01);  // 300 chunks
  // Reused this frame (limit "any"): next frame ages 2 -> 3 (100 chunks), 1 -> 2 (400); the fill (50) -> 1.
  const auto limit = budget.nextAgeLimit(50, 50, ages({{1, 400}, {2, 100}}), {});
  // 250 to spend: all 100 of age 3, then 150 of the 400 of age 2.
  EXPECT_EQ(limit.limit, 2u);
  EXPECT_EQ(limit.fraction, 150u * kWholeFraction / 400u);
}

TEST(ShadeBudgetTest, TheFillComesFirst) {
  const ShadeBudget budget(1.0, 0.01);  // 100 chunks, all taken by the fill
  const auto limit = budget.nextAgeLimit(120, 120, ages({{3, 500}}), {});
  EXPECT_EQ(limit.fraction, 0u) << "nothing left for stale chunks";
  EXPECT_EQ(limit.limit, 4u);
}

TEST(ShadeBudgetTest, LearnsTheCostPerChunk) {
  ShadeBudget budget(10.0, 0.01);
  for (int i = 0; i < 40; ++i) budget.observeCost(20.0, 1000);  // 0.02 ms a chunk
  EXPECT_NEAR(budget.msPerChunk(), 0.02, 1e-4);
  budget.observeCost(50.0, 10);  // too few chunks to tell: ignored
  EXPECT_NEAR(budget.msPerChunk(), 0.02, 1e-4);
  EXPECT_EQ(budget.budgetChunks(), 500u);
}

}  // namespace
}  // namespace sg::plugins
