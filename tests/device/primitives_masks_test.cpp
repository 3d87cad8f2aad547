// Multi-primitive meshes (each primitive its own decoupled object, with its
// own material) and alpha-mask materials (alpha-tested in the z-prepass,
// shadel-mark and composite) through both paths, validation on: every object
// decoupled shading takes is decoupled, decoupled agrees with forward
// (>= 30 dB) from a few cameras, and no composite lookup misses.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/scene/camera.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 256;

// MorphPrimitivesTest's texture (a fine UV grid with text) has no mipmaps
// (minFilter LINEAR): minified, forward aliases it where decoupled, shading at
// shadel density, does not (29.6 dB at 256², from above). Closer to its
// texture's resolution the comparison is about the shading again.
uint32_t sizeFor(const std::string& name) { return name == "MorphPrimitivesTest" ? 512 : kSize; }

// The model from the front (frameBounds), from above on the left and from the
// lower right, at the same distance.
std::vector<scene::Camera> cameras(const scene::Scene& scene) {
  const scene::Bounds bounds = scene::worldBounds(scene);
  const scene::Camera front = scene::frameBounds(bounds, 1.0f);
  const glm::vec3 center = bounds.center();
  const float distance = glm::length(front.position() - center);
  std::vector<scene::Camera> all{front};
  for (const glm::vec3 dir : {glm::vec3(-0.5f, 0.8f, 0.5f), glm::vec3(0.75f, -0.25f, 0.6f)}) {
    scene::Camera c = front;
    c.world = scene::lookAtWorld(center + glm::normalize(dir) * distance, center);
    all.push_back(c);
  }
  return all;
}

class PrimitivesAndMasks : public ::testing::TestWithParam<const char*> {};

TEST_P(PrimitivesAndMasks, AllDecoupledAndAgreeWithForward) {
  const std::string name = GetParam();
  if (!std::filesystem::exists(samplePath(name)))
    GTEST_SKIP() << "asset not found under " << assetsDir() << " (../shared/assets/gltf)";
  const scene::Scene loaded = scene::loadGltf(samplePath(name));
  const auto views = cameras(loaded);
  Session f(loaded, scene::ShadingMode::Forward);
  Session d(loaded, scene::ShadingMode::Decoupled, {.storageChunks = 16384});
  // Every primitive decoupled shading takes is decoupled: all but alpha-blended ones.
  size_t multiPrimitive = 0, masked = 0;
  for (const auto& choice : d.choices()) {
    const scene::Mesh& mesh = d.scene().meshes[size_t(d.scene().instances[choice.instance].mesh)];
    multiPrimitive += mesh.primitives.size() > 1 ? 1 : 0;
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const scene::AlphaMode mode = d.scene().materials[size_t(mesh.primitives[p].material)].alphaMode;
      masked += mode == scene::AlphaMode::Mask ? 1 : 0;
      if (mode == scene::AlphaMode::Blend) {
        EXPECT_FALSE(choice.primitives[p].eligible);
        EXPECT_NE(choice.primitives[p].reason.find("alpha-blended"), std::string::npos) << choice.primitives[p].reason;
      } else {
        EXPECT_TRUE(choice.decoupled && choice.primitives[p].eligible)
            << name << " object " << choice.instance << " primitive " << p << ": " << choice.reason;
      }
    }
  }
  EXPECT_GT(multiPrimitive + masked, 0u) << name << " has neither multi-primitive meshes nor alpha-mask materials";
  uint64_t misses = 0;
  for (size_t k = 0; k < views.size(); ++k) {
    const gpu::HostImage forward = f.render(sizeFor(name), views[k]);
    const gpu::HostImage decoupled = d.render(sizeFor(name), views[k]);
    const auto stats = d.stats();
    EXPECT_GT(stats.objects, 0u) << name << " camera " << k << ": nothing was shaded decoupled";
    misses += stats.counters.compositeMisses;
    // Nor does running leave any forward (MetalRoughSpheresNoTextures' 123
    // triangle-ID maps once outgrew the one buffer).
    for (const auto& left : d.shading().runTimeForward())
      ADD_FAILURE() << name << " object " << left.instance << " primitive " << left.primitive
                    << " forward at run time: " << left.reason;
    const auto diff = image::compareRgba8(forward.rgba8, decoupled.rgba8);
    std::printf("%-28s camera %zu: %u objects decoupled, PSNR %.2f dB, %.2f%% pixels > 8/255, %u misses\n",
                name.c_str(), k, stats.objects, diff.psnr, 100.0 * diff.fractionAbove8, stats.counters.compositeMisses);
    EXPECT_GE(diff.psnr, 30.0) << name << " camera " << k;
    if (HasFailure() || std::getenv("SG_KEEP_RENDERS"))
      for (const auto& [path, image] : {std::pair{"forward", &forward}, std::pair{"decoupled", &decoupled}})
        image::writePng(std::filesystem::temp_directory_path() /
                            ("sg-" + name + "-" + path + "-" + std::to_string(k) + ".png"),
                        image->width, image->height, image->rgba8.data());
  }
  EXPECT_EQ(misses, 0u) << name;
}

// Multi-primitive: MorphPrimitivesTest (2 primitives with overlapping UVs,
// morphed), MetalRoughSpheresNoTextures (up to 9 primitives, no UVs: an
// automatic chart each). Alpha-mask: AlphaBlendModeTest's three cutoffs over a
// texture whose alpha ramps (its two blended quads stay forward). CAD
// meshes: 2CylinderEngine (parts full of triangles of zero surface area, which
// the automatic charts need not hold; two meshes of two primitives).
INSTANTIATE_TEST_SUITE_P(Models, PrimitivesAndMasks,
                         ::testing::Values("MorphPrimitivesTest", "MetalRoughSpheresNoTextures", "AlphaBlendModeTest",
                                           "2CylinderEngine"),
                         [](const auto& param) { return std::string(param.param); });

}  // namespace
}  // namespace sg::test
