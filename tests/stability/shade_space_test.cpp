// Shade-space hard cases, validation on: storage at 1% of what bias 0 needs
// (the adjuster must degrade quality, never corrupt), bias extremes, and an
// object whose layer-shade dispatch needs more than the 65,535 workgroups one
// dimension may have.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <ostream>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 128;

// At 512x512: at 128x128, 1% is 2 chunks, fewer than the three objects' coarsest levels need.
TEST(ShadeSpace, StorageAtOnePercentDegradesWithoutCorrupting) {
  constexpr uint32_t kLarge = 512;
  const scene::Scene s = makeLitSet();
  uint32_t needed = 0;
  {
    StabilitySession ample(s, scene::ShadingMode::Decoupled, {.storageChunks = 16384, .fixedBias = 0.0f});
    needed = ample.render(kLarge).stats.counters.chunksMarked;
  }
  // At least 4 chunks: the coarsest levels of the set's objects fill 3, and
  // storage they fill above 92% keeps the adjuster raising the bias to its clamp.
  const uint32_t storage = std::max(4u, needed / 100);
  std::printf("bias 0 marks %u chunks; storage %u chunks\n", needed, storage);
  StabilitySession pressured(s, scene::ShadingMode::Decoupled, {.storageChunks = storage});
  StabilityFrame frame;
  std::vector<float> biases;
  for (int i = 0; i < 16; ++i) {
    frame = pressured.render(kLarge);
    expectFinite(frame, "frame " + std::to_string(i));
    biases.push_back(frame.stats.bias);
    std::printf("frame %2d bias %.3f marked %u allocated %u overflow %u misses %u\n", i, double(frame.stats.bias),
                frame.stats.counters.chunksMarked, frame.stats.counters.chunksAllocated,
                frame.stats.counters.overflowChunks, frame.stats.counters.compositeMisses);
  }
  // Settled: a steady bias, and the last frames neither overflow nor miss.
  EXPECT_GT(biases.back(), 2.0f) << "1% of the storage needs about log4(100) = 3.3 levels coarser";
  EXPECT_LT(std::abs(biases.back() - biases[biases.size() - 4]), 0.01f);
  expectClean(frame, "settled at 1% storage");
  // Coarser, not garbage: the same bias with ample storage renders the same frame.
  StabilitySession reference(s, scene::ShadingMode::Decoupled, {.storageChunks = 16384, .fixedBias = biases.back()});
  expectAgreement(frame, reference.render(kLarge), {45.0, 0.5}, "1% storage vs ample at the settled bias");
}

struct BiasCase {
  const char* name;
  float bias;
  Bound vsForward;
};

void PrintTo(const BiasCase& c, std::ostream* os) { *os << c.name; }

class BiasExtremes : public ::testing::TestWithParam<BiasCase> {};

TEST_P(BiasExtremes, StayFiniteAndWatertight) {
  const BiasCase c = GetParam();
  // A bias below zero asks for 4^-bias more shadels: storage to match, so nothing overflows.
  const double factor = 2.0 * std::pow(4.0, std::max(0.0, -double(c.bias))) * 1.5;
  const BothPaths both =
      renderBothPaths(makeLitSet(), kSize, kSize, {}, {.storageFactor = factor, .fixedBias = c.bias});
  const std::string what = std::string("bias ") + c.name;
  expectClean(both.decoupled, what);
  expectAgreement(both.decoupled, both.forward, c.vsForward, what + ": decoupled vs forward");
}

INSTANTIATE_TEST_SUITE_P(Biases, BiasExtremes,
                         // Measured: -2: 33.8 dB, 2.2/255 (shadels finer than the textures: forward's
                         // own aliasing differs); +6: 26.0 dB, 7.1/255 (6 levels coarser: blur).
                         ::testing::Values(BiasCase{"-2", -2.0f, {32.0, 2.5}}, BiasCase{"+6", 6.0f, {24.0, 8.5}}),
                         [](const auto& testInfo) { return testInfo.param.bias < 0 ? std::string("Minus2") : std::string("Plus6"); });

// A 16:9 plane whose level 0 is 2048 shadels a side (from its 2048-texel
// texture) just overfills the 2560x1440 view: about 1.4 shadels a pixel
// vertically, so composite reads levels 0 and 1, 95% of each visible. That is
// about 62,500 + 15,600 chunks for one object, one workgroup each: more than
// one dispatch dimension allows.
TEST(ShadeSpace, ScreenFillingObjectAt2560x1440ExceedsOneDispatchDimension) {
  constexpr uint32_t kTexels = 2048;
  scene::Scene s;
  s.samplers.push_back({});
  scene::Texture big{.name = "big checker", .width = kTexels, .height = kTexels};
  big.pixels.resize(size_t(kTexels) * kTexels * 4);
  for (uint32_t y = 0; y < kTexels; ++y)
    for (uint32_t x = 0; x < kTexels; ++x) {
      uint8_t* p = &big.pixels[(size_t(y) * kTexels + x) * 4];
      const bool odd = ((x / 32) + (y / 32)) % 2;
      p[0] = odd ? 200 : 60;
      p[1] = uint8_t(80 + (x * 97 + y * 31) % 64);
      p[2] = odd ? 70 : 180;
      p[3] = 255;
    }
  s.textures.push_back(std::move(big));
  scene::Material m{.name = "big checker", .metallicFactor = 0.0f, .roughnessFactor = 0.7f};
  m.baseColorTexture.texture = 0;
  placeMesh(s, scene::makePlane(16.4f, 9.2f, 4), addMaterial(s, m),
            glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), {1.0f, 0.0f, 0.0f}));  // facing +Z
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 2.5f,
                      .direction = glm::normalize(glm::vec3(-0.2f, -0.3f, -1.0f))});
  // From 9 units: 9 units of height and 16 of width in view.
  const scene::Camera camera =
      cameraAt({0.0f, 0.0f, 9.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 100.0f, 2.0f * std::atan(0.5f));
  // Trilinear: it marks two levels, enough chunks to pass the dispatch limit
  // (bilinear, the default, marks ~63000 here).
  const BothPaths both = renderBothPaths(s, 2560, 1440, camera, {.filter = 2});
  const auto c = both.decoupled.stats.counters;
  std::printf("2560x1440: %u chunks allocated for one object (dispatch limit 65535), %u covered pixels\n",
              c.chunksAllocated, c.coveredPixels);
  EXPECT_GT(c.chunksAllocated, 65535u) << "the case must need more workgroups than one dimension holds";
  expectFinite(both.forward, "2560x1440 forward");
  expectClean(both.decoupled, "2560x1440 decoupled");
  expectAgreement(both.decoupled, both.forward, {}, "2560x1440: decoupled vs forward");
}

}  // namespace
}  // namespace sg::test
