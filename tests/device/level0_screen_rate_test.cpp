// Level 0 at the screen's rate (validation on): an untextured model whose
// level 0 the triangle count alone put at 64² (OrientationTest: a bevelled
// cube of 140 triangles) was read magnified about 8 times, so its bevels,
// a few pixels wide, vanished decoupled (27 dB against forward at 640x360).
// With level 0 at least the view's pixels per chart unit, it agrees with
// forward (42 dB; at 256² only 32: the bevels are a pixel or two wide there
// and every crease between a face and its bevel is filtered over a shadel).
#include <gtest/gtest.h>

#include <cstdio>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

TEST(DecoupledLevel0, ThinBevelsAreShadedAtTheScreensRate) {
  SG_REQUIRE_ASSETS();
  const scene::Scene scene = scene::loadGltf(samplePath("OrientationTest"));
  const render::RenderSettings size{.width = 640, .height = 360};
  const gpu::HostImage forward = forwardImage(scene, size);
  double psnr[2] = {};
  for (const bool screenRate : {false, true}) {
    Session d(scene, scene::ShadingMode::Decoupled,
              {.storageChunks = 16384, .fixedBias = 0.0f, .screenRateLevel0 = screenRate});
    const gpu::HostImage decoupled = d.renderer().render(size).image;
    const auto stats = d.stats();
    EXPECT_EQ(stats.objects, 13u);
    EXPECT_EQ(stats.counters.compositeMisses, 0u);
    const auto diff = image::compareRgba8(forward.rgba8, decoupled.rgba8);
    std::printf("OrientationTest decoupled (level 0 %s) vs forward at 640x360: PSNR %.2f dB, mean |d| %.2f/255\n",
                screenRate ? "at the screen's rate" : "from the triangle count", diff.psnr, diff.meanAbs);
    psnr[screenRate] = diff.psnr;
  }
  EXPECT_LT(psnr[0], 35.0) << "the bevels should vanish without the screen term (what this test is about)";
  EXPECT_GE(psnr[1], 40.0);
}

}  // namespace
}  // namespace sg::test
