// The forward pass's plain variant (position and normal the only varyings,
// for draws whose material has no texture and whose mesh has no COLOR_0)
// draws what the full variant draws: the same model with an all-ones COLOR_0
// (which shades identically but needs the full variant) gives the same image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

size_t plainDraws(Session& session) {
  const auto& draws = session.renderer().gpuScene().draws();
  return size_t(std::count_if(draws.begin(), draws.end(), [](const render::DrawItem& d) { return d.plainSurface; }));
}

class PlainSurface : public ::testing::TestWithParam<const char*> {};

TEST_P(PlainSurface, DrawsWhatTheFullVariantDraws) {
  SG_REQUIRE_ASSETS();
  const scene::Scene plain = scene::loadGltf(samplePath(GetParam()));
  scene::Scene coloured = plain;
  for (auto& mesh : coloured.meshes)
    for (auto& primitive : mesh.primitives) primitive.colors.assign(primitive.positions.size(), glm::vec4(1.0f));

  Session a(plain, scene::ShadingMode::Forward), b(coloured, scene::ShadingMode::Forward);
  EXPECT_EQ(plainDraws(a), a.renderer().gpuScene().draws().size());  // untextured models: every draw is plain
  EXPECT_EQ(plainDraws(b), 0u);
  const auto imageA = a.render(256), imageB = b.render(256);

  // The model is in the picture: not every pixel is the background's (the corner's).
  const uint8_t* corner = imageA.pixel(0, 0);
  size_t covered = 0;
  for (uint32_t y = 0; y < imageA.height; ++y)
    for (uint32_t x = 0; x < imageA.width; ++x) covered += !std::equal(corner, corner + 3, imageA.pixel(x, y));
  EXPECT_GT(covered, 256u * 256u / 50);

  const auto d = image::compareRgba8(imageA.rgba8, imageB.rgba8);
  std::printf("%s plain vs full forward variant: max |d| %d/255, covered %zu pixels\n", GetParam(), d.maxAbs, covered);
  EXPECT_LE(d.maxAbs, 1);
}

INSTANTIATE_TEST_SUITE_P(Models, PlainSurface, ::testing::Values("Box", "2CylinderEngine"),
                         [](const auto& testInfo) { return std::string(testInfo.param); });

}  // namespace
}  // namespace sg::test
