// A glTF camera rendered at two output shapes, validation on: the object keeps
// its proportions. The camera's vertical field of view is kept and the output's
// aspect used, whatever the camera's `aspectRatio` says, so going from 256x256
// to 512x256 shows more of the scene sideways: the object keeps its size in
// pixels (stretching would make it 2/aspectRatio times as wide), and the wide
// image's middle 256 columns are the square image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <builtin_plugins.hpp>
#include <builtin_shaders.hpp>
#include <decoupled/decoupled_package.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/render/renderer.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "device_fixture.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

struct Case {
  const char* model;  // a sample model with a camera whose aspectRatio differs from 512x256's 2.0
  scene::ShadingMode mode;
  // The file's camera with its yfov times this (aspectRatio untouched): the
  // 2CylinderEngine's own camera crops the engine, whose box must be whole.
  float yfovScale = 1.0f;
};

std::string caseName(const Case& c) {
  return std::string(c.model) + "_" + (c.mode == scene::ShadingMode::Forward ? "forward" : "decoupled");
}

// Pixels that differ from the background (the top-left pixel) by more than
// this in some channel belong to the object.
constexpr int kBackgroundTolerance = 12;

struct PixelBox {
  uint32_t minX = ~0u, minY = ~0u, maxX = 0, maxY = 0;
  bool empty() const { return minX > maxX; }
  uint32_t width() const { return maxX - minX + 1; }
  uint32_t height() const { return maxY - minY + 1; }
};

PixelBox objectBox(const gpu::HostImage& image) {
  PixelBox box;
  const uint8_t* background = image.rgba8.data();
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const uint8_t* p = image.rgba8.data() + 4 * (size_t(y) * image.width + x);
      bool object = false;
      for (int c = 0; c < 3; ++c) object |= std::abs(int(p[c]) - int(background[c])) > kBackgroundTolerance;
      if (!object) continue;
      box.minX = std::min(box.minX, x), box.maxX = std::max(box.maxX, x);
      box.minY = std::min(box.minY, y), box.maxY = std::max(box.maxY, y);
    }
  return box;
}

class CameraAspect : public ::testing::TestWithParam<Case> {};

TEST_P(CameraAspect, ObjectKeepsItsProportionsAtAnyOutputShape) {
  const Case c = GetParam();
  const auto file = samplePath(c.model);
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "asset not found: " << file << " (../shared/assets/gltf absent)";
  scene::Scene s = scene::loadGltf(file);
  ASSERT_FALSE(s.cameras.empty()) << c.model << " has no camera";
  ASSERT_TRUE(s.cameras.front().aspectRatio) << c.model << "'s camera has no aspectRatio";
  ASSERT_NE(*s.cameras.front().aspectRatio, 2.0f) << "the wide render must differ from the camera's aspect";
  scene::Camera camera = s.cameras.front();
  camera.yfov *= c.yfovScale;

  gpu::HostImage square, wide;
  {
    gpu::Context context(validatedOptions());
    {
      gpu::Device device(context);
      device.shaders().add(gpu::builtinShaders());
      auto made = plugins::makeDecoupledRenderer(device, s, plugins::builtinRegistry(), c.mode);
      square = made.renderer->render({.width = 256, .height = 256, .cameraOverride = camera}).image;
      wide = made.renderer->render({.width = 512, .height = 256, .cameraOverride = camera}).image;
      if (c.mode == scene::ShadingMode::Decoupled) {
        EXPECT_GT(made.shading->stats().objects, 0u) << "nothing was shaded decoupled";
        EXPECT_EQ(made.shading->stats().counters.compositeMisses, 0u);
      }
    }
    for (const auto& m : context.validationLog().messages()) ADD_FAILURE() << "validation: " << m.text;
  }
  const std::string name = caseName(c);
  if (const char* dir = std::getenv("SG_TEST_IMAGES")) {  // to look at them
    image::writePng(std::string(dir) + "/camera-aspect-" + name + "-256x256.png", square.width, square.height,
                    square.rgba8.data());
    image::writePng(std::string(dir) + "/camera-aspect-" + name + "-512x256.png", wide.width, wide.height,
                    wide.rgba8.data());
  }

  // The same projection, only wider: the middle of the wide image is the square
  // one, up to automatic exposure (the log-average luminance of the whole frame
  // moves with the extra background), a small shift of every pixel. A stretched
  // projection differs at most of the object's pixels.
  std::vector<uint8_t> middle;
  for (uint32_t y = 0; y < 256; ++y) {
    const auto row = wide.rgba8.begin() + 4 * (ptrdiff_t(y) * 512 + 128);
    middle.insert(middle.end(), row, row + 4 * 256);
  }
  const image::ImageDifference d = image::compareRgba8(middle, square.rgba8);
  std::printf("%-24s middle 256x256 of 512x256 vs 256x256: mean |d| %.3f/255, %.2f%% pixels > 8/255\n",
              caseName(c).c_str(), d.meanAbs, 100.0 * d.fractionAbove8);
  EXPECT_LT(d.fractionAbove8, 0.01) << caseName(c);

  const PixelBox a = objectBox(square), b = objectBox(wide);
  ASSERT_FALSE(a.empty()) << name << ": nothing drawn at 256x256";
  ASSERT_FALSE(b.empty()) << name << ": nothing drawn at 512x256";
  std::printf("%-24s object box: 256x256 -> %ux%u px at (%u,%u); 512x256 -> %ux%u px at (%u,%u)\n", name.c_str(),
              a.width(), a.height(), a.minX, a.minY, b.width(), b.height(), b.minX, b.minY);
  // The whole object is in view at both shapes, else its box measures the frame.
  ASSERT_TRUE(a.minX > 0 && a.minY > 0 && a.maxX + 1 < square.width && a.maxY + 1 < square.height)
      << name << ": the object touches the border of the 256x256 render";
  ASSERT_TRUE(b.minX > 0 && b.minY > 0 && b.maxX + 1 < wide.width && b.maxY + 1 < wide.height)
      << name << ": the object touches the border of the 512x256 render";

  // Same height: the vertical field of view is the camera's at both shapes.
  EXPECT_NEAR(double(b.height()), double(a.height()), 2.0) << name;
  // Same width: the extra output width shows more scene, it does not stretch the object.
  EXPECT_NEAR(double(b.width()), double(a.width()), 2.0) << name;
  // And the object stays where it was relative to the image centre.
  EXPECT_NEAR(double(b.minX) - 128.0, double(a.minX), 2.0) << name;
  EXPECT_NEAR(double(b.minY), double(a.minY), 2.0) << name;
}

INSTANTIATE_TEST_SUITE_P(Models, CameraAspect,
                         // 2CylinderEngine has no unique chart (it is drawn forward in any mode).
                         ::testing::Values(Case{"2CylinderEngine", scene::ShadingMode::Forward, 1.6f},
                                           Case{"Duck", scene::ShadingMode::Forward},
                                           Case{"Duck", scene::ShadingMode::Decoupled}),
                         [](const auto& testInfo) { return caseName(testInfo.param); });

}  // namespace
}  // namespace sg::test
