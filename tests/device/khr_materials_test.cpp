// The glTF material extensions as layer stacks on the device, validation on:
// each test asset (tests/assets/khr-materials) renders decoupled and forward
// from the one source per layer and the two agree (>= 30 dB), runs the stack
// its extensions call for, and differs from the same asset without the
// extension where and how the extension says it should.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 160;
// The asset's camera (z 3.4, yfov 0.7) sees the unit sphere as a disc of this radius around the centre.
const double kDiscRadius = std::tan(std::asin(1.0 / 3.4)) / std::tan(0.35) * kSize / 2.0;

struct Pixel {
  double r, g, b;
  double luminance() const { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
};

Pixel at(const gpu::HostImage& image, uint32_t x, uint32_t y) {
  const uint8_t* p = &image.rgba8[(size_t(y) * image.width + x) * 4];
  return {double(p[0]), double(p[1]), double(p[2])};
}

// Distance from the image centre in disc radii.
double discRadius(uint32_t x, uint32_t y) {
  return std::hypot(x + 0.5 - kSize / 2.0, y + 0.5 - kSize / 2.0) / kDiscRadius;
}

// The mean over the disc pixels between radii `from` and `to` of f(with, without).
double meanOver(const gpu::HostImage& with, const gpu::HostImage& without, double from, double to,
                const std::function<double(Pixel, Pixel)>& f) {
  double sum = 0.0;
  size_t n = 0;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      if (const double r = discRadius(x, y); r >= from && r < to) {
        sum += f(at(with, x, y), at(without, x, y));
        ++n;
      }
  return n ? sum / double(n) : 0.0;
}

struct Brightening {
  double amount = -1e9;
  uint32_t x = 0, y = 0;
};

// Where the luminance grew most.
Brightening mostBrightened(const gpu::HostImage& with, const gpu::HostImage& without) {
  Brightening best;
  for (uint32_t y = 0; y < kSize; ++y)
    for (uint32_t x = 0; x < kSize; ++x)
      if (const double d = at(with, x, y).luminance() - at(without, x, y).luminance(); d > best.amount) best = {d, x, y};
  return best;
}

void save(const gpu::HostImage& image, const std::string& name) {
  if (const char* dir = std::getenv("SG_TEST_IMAGES"))  // to look at them
    image::writePng(std::string(dir) + "/" + name + ".png", image.width, image.height, image.rgba8.data());
}

struct Asset {
  const char* name;
  std::vector<std::string> layers;         // the stack the decoupled frame runs
  std::function<void(scene::Material&)> strip;  // removes the extension
};

class KhrMaterials : public ::testing::TestWithParam<Asset> {
 protected:
  scene::Scene load() const {
    return scene::loadGltf(std::filesystem::path(SG_SOURCE_DIR) / "tests/assets/khr-materials" /
                           (std::string(GetParam().name) + ".gltf"));
  }
  scene::Scene stripped() const {
    scene::Scene s = load();
    for (auto& m : s.materials) GetParam().strip(m);
    return s;
  }
  // The asset (or its stripped copy) in `mode`: the image, and the decoupled stats when decoupled.
  gpu::HostImage render(scene::Scene s, scene::ShadingMode mode, const std::string& label) {
    Session session(std::move(s), mode);
    const auto image = session.render(kSize);
    save(image, std::string(GetParam().name) + "-" + label);
    if (mode == scene::ShadingMode::Decoupled) {
      const auto stats = session.stats();
      EXPECT_EQ(stats.objects, 1u) << "the sphere is shaded decoupled";
      EXPECT_EQ(stats.counters.compositeMisses, 0u);
      if (label == "decoupled") {
        EXPECT_EQ(stats.layers, GetParam().layers);
        EXPECT_EQ(stats.layerDispatches, GetParam().layers.size()) << "one dispatch per layer of its stack";
      }
    }
    return image;
  }
};

TEST_P(KhrMaterials, DecoupledAgreesWithForward) {
  const auto decoupled = render(load(), scene::ShadingMode::Decoupled, "decoupled");
  const auto forward = render(load(), scene::ShadingMode::Forward, "forward");
  const auto d = image::compareRgba8(decoupled.rgba8, forward.rgba8);
  std::printf("%-10s decoupled vs forward: PSNR %.2f dB, mean |d| %.2f/255\n", GetParam().name, d.psnr, d.meanAbs);
  EXPECT_GE(d.psnr, 30.0);
}

TEST_P(KhrMaterials, TheExtensionIsVisible) {
  const std::string name = GetParam().name;
  const auto with = render(load(), scene::ShadingMode::Forward, "forward");
  const auto without = render(stripped(), scene::ShadingMode::Forward, "without");
  // Decoupled, the stripped asset is plain gltf-pbr.
  const auto strippedDecoupled = render(stripped(), scene::ShadingMode::Decoupled, "without-decoupled");
  EXPECT_GE(image::compareRgba8(strippedDecoupled.rgba8, without.rgba8).psnr, 30.0);
  const Brightening most = mostBrightened(with, without);
  const auto lum = [](Pixel a, Pixel b) { return a.luminance() - b.luminance(); };
  const double centre = meanOver(with, without, 0.0, 0.5, lum), rim = meanOver(with, without, 0.8, 0.97, lum);
  const double warmth = meanOver(with, without, 0.0, 0.97, [](Pixel a, Pixel b) { return (a.r - a.b) - (b.r - b.b); });
  std::printf("%-10s with vs without: most brightened %+.1f at (%u, %u); luminance change centre %+.2f, rim %+.2f; "
              "red - blue %+.2f\n", name.c_str(), most.amount, most.x, most.y, centre, rim, warmth);
  // The sun is up and to the left, in front: its highlight lies in the upper left quarter.
  const bool upperLeft = most.x < kSize / 2 && most.y < kSize / 2;
  if (name == "clearcoat") {
    EXPECT_GT(most.amount, 40.0) << "the smooth coat adds a sharp second highlight on the rough base";
    EXPECT_TRUE(upperLeft) << "where the sun's reflection is";
  } else if (name == "sheen") {
    EXPECT_GT(rim, 5.0) << "microfibres light up at grazing angles";
    EXPECT_GT(rim, centre + 3.0) << "more at the rim than facing the camera";
  } else if (name == "specular") {
    EXPECT_GT(warmth, 1.0) << "reflections tinted by specularColorFactor (6, 2, 0.25): red up, blue down";
  } else if (name == "ior") {
    EXPECT_GT(most.amount, 20.0) << "f0 0.17 instead of 0.04: a brighter highlight";
    EXPECT_TRUE(upperLeft);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Assets, KhrMaterials,
    ::testing::Values(
        Asset{"clearcoat", {"gltf-pbr", "gltf-pbr-clearcoat"}, [](scene::Material& m) { m.clearcoat.reset(); }},
        Asset{"sheen", {"gltf-pbr", "gltf-pbr-sheen"}, [](scene::Material& m) { m.sheen.reset(); }},
        Asset{"specular", {"dielectric-specular", "gltf-pbr-specular"}, [](scene::Material& m) { m.specular.reset(); }},
        Asset{"ior", {"dielectric-specular", "gltf-pbr-specular"}, [](scene::Material& m) { m.ior.reset(); }}),
    [](const ::testing::TestParamInfo<Asset>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace sg::test
