// Image tests: scenes rendered forward at 256x256 on the device (validation
// on) compared with the golden PNGs in tests/image/golden. Tolerance: at most
// 0.5% of pixels may differ by more than 8/255 in any channel, and the mean
// absolute difference must stay under 1/255 — tight enough to catch a wrong
// texture, transform or light, loose enough for rasterizer differences
// between Mesa versions. SG_UPDATE_GOLDEN=1 rewrites the goldens (look at
// them before committing).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include <builtin_shaders.hpp>
#include <builtin_plugins.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/render/renderer.hpp>
#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "../device/device_fixture.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

struct Case {
  const char* name;  // golden file name; also the asset folder, except "DefaultScene"
};

class GoldenImage : public ::testing::TestWithParam<Case> {};

gpu::HostImage renderScene(const scene::Scene& s) {
  gpu::Context context(validatedOptions());
  gpu::HostImage image;
  {
    gpu::Device device(context);
    device.shaders().add(gpu::builtinShaders());
    const auto& registry = plugins::builtinRegistry();
    render::Renderer renderer(device, s, registry, plugin::resolveFrame(registry.frame("forward"), registry));
    image = renderer.render({.width = 256, .height = 256}).image;
  }
  for (const auto& m : context.validationLog().messages()) ADD_FAILURE() << "validation: " << m.text;
  return image;
}

TEST_P(GoldenImage, MatchesGolden) {
  const std::string name = GetParam().name;
  scene::Scene s;
  if (name == "DefaultScene") {
    s = scene::makeDefaultScene();
  } else {
    const auto file = samplePath(name);
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "asset not found: " << file << " (../shared/assets/gltf absent)";
    s = scene::loadGltf(file);
  }
  const gpu::HostImage image = renderScene(s);
  const auto golden = std::filesystem::path(SG_SOURCE_DIR) / "tests/image/golden" / (name + ".png");
  if (const char* update = std::getenv("SG_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    image::writePng(golden, image.width, image.height, image.rgba8.data());
    GTEST_SKIP() << "golden rewritten: " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << "missing golden " << golden << " (SG_UPDATE_GOLDEN=1 creates it)";
  const auto expected = image::readPng(golden);
  ASSERT_EQ(expected.width, image.width);
  ASSERT_EQ(expected.height, image.height);
  size_t far = 0;
  double sum = 0;
  for (size_t i = 0; i < image.rgba8.size(); i += 4) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(image.rgba8[i + c]) - int(expected.pixels[i + c]));
      worst = std::max(worst, d);
      sum += d;
    }
    far += worst > 8;
  }
  const size_t pixels = image.rgba8.size() / 4;
  const double mean = sum / double(pixels * 3);
  EXPECT_LE(far, pixels / 200) << name << ": " << far << " pixels differ by more than 8/255";
  EXPECT_LT(mean, 1.0) << name << ": mean absolute difference " << mean << "/255";
  if (HasFailure()) {
    const auto actual = std::filesystem::temp_directory_path() / ("sg-golden-" + name + ".png");
    image::writePng(actual, image.width, image.height, image.rgba8.data());
    ADD_FAILURE() << "this render: " << actual;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GoldenImage,
                         ::testing::Values(Case{"DefaultScene"}, Case{"DamagedHelmet"}, Case{"BoxTextured"},
                                           Case{"AlphaBlendModeTest"}, Case{"VertexColorTest"},
                                           Case{"TextureCoordinateTest"}, Case{"TextureSettingsTest"},
                                           Case{"NormalTangentMirrorTest"}),
                         [](const auto& testInfo) { return std::string(testInfo.param.name); });

}  // namespace
}  // namespace sg::test
