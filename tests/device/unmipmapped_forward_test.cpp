// Auto mode and textures without mip levels (validation on): TextureTransformTest
// samples UV.png and Arrow.png with minFilter LINEAR, no mips. At 640x360 they
// are minified: forward reads every pixel from the full
// texture, decoupled shadels a pixel apart lose the thin lines and blur the
// letter edges (33.6 dB against forward). Auto mode now draws those objects
// forward in such frames and says why (1.5-2.5 texels per pixel there); at
// 1280x720 (under one texel per pixel) they stay decoupled.
#include <gtest/gtest.h>

#include <cstdio>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

// The last frame's objects drawn forward because of a minified texture without mips.
size_t minifiedForward(Session& session) {
  size_t count = 0;
  for (const auto& f : session.shading().frameForward())
    count += f.reason.find("has no mip levels and is minified") != std::string::npos;
  return count;
}

TEST(DecoupledAuto, MinifiedTexturesWithoutMipsAreShadedForward) {
  SG_REQUIRE_ASSETS();
  const scene::Scene scene = scene::loadGltf(samplePath("TextureTransformTest"));
  const render::RenderSettings small{.width = 640, .height = 360};
  const gpu::HostImage forward = forwardImage(scene, small);
  double psnr[2] = {};
  for (const bool verdict : {false, true}) {
    Session a(scene, scene::ShadingMode::Auto, {.storageChunks = 16384, .fixedBias = 0.0f,
                                                 .forwardMinifiedUnmipmapped = verdict});
    const gpu::HostImage image = a.renderer().render(small).image;
    const auto stats = a.stats();
    EXPECT_EQ(stats.counters.compositeMisses, 0u);
    // The three small "Correct" quads are tiny on screen: forward either way.
    if (verdict) {
      // The six quads of UV.png and Arrow.png go forward, and say why; the
      // three of Correct, NotSupported and Error (mipmapped) stay decoupled.
      EXPECT_EQ(stats.objects, 3u);
      EXPECT_EQ(minifiedForward(a), 6u);
    } else {
      EXPECT_EQ(stats.objects, 9u);
      EXPECT_EQ(minifiedForward(a), 0u);
    }
    const auto diff = image::compareRgba8(forward.rgba8, image.rgba8);
    std::printf("TextureTransformTest auto (%s) vs forward at 640x360: PSNR %.2f dB\n",
                verdict ? "minified unmipmapped textures forward" : "all decoupled", diff.psnr);
    psnr[verdict] = diff.psnr;
  }
  EXPECT_LT(psnr[0], 36.0) << "decoupled should lose the minified texture's detail (what this test is about)";
  EXPECT_GE(psnr[1], 40.0);

  // Twice the size: under one texel per pixel, every object decoupled.
  Session a(scene, scene::ShadingMode::Auto, {.storageChunks = 16384, .fixedBias = 0.0f});
  a.renderer().render({.width = 1280, .height = 720});
  EXPECT_EQ(a.stats().objects, 12u);
  EXPECT_EQ(minifiedForward(a), 0u);
}

}  // namespace
}  // namespace sg::test
