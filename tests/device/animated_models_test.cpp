// Skinned, morphed and node-animated sample models through both paths, with
// validation on: images at two times (the pose must change them), decoupled
// against forward (>= 30 dB), no composite misses along a 30-frame playback,
// and the GPU skinning pass against the CPU reference (scene::deformVertex).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <shadelgraph/gpu/context.hpp>
#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/scene/deformation.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/pose.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;

// Poses `scene` (the test's copy: nodes, skins, weights) at `t` and hands every
// object's transform, joint matrices and morph weights to `renderer`, as the
// CLI's animation player does.
void poseAt(scene::Scene& scene, render::Renderer& renderer, float t) {
  const std::vector<int> all = scene::allAnimations(scene);
  const std::vector<glm::mat4> world = scene::poseNodes(scene, all, t);
  scene::applyPose(scene, world);
  scene::applyWeights(scene, scene::poseWeights(scene, all, t));
  for (uint32_t i = 0; i < scene.instances.size(); ++i) {
    const scene::Instance& instance = scene.instances[i];
    renderer.setObjectTransform(i, instance.world);
    if (!renderer.gpuScene().deformation().deformed(i)) continue;
    const auto joints = instance.skin >= 0 ? scene::jointWorldMatrices(scene.skins[size_t(instance.skin)], world)
                                           : std::vector<glm::mat4>{};
    renderer.setObjectDeformation(i, joints, instance.morphWeights);
  }
}

float duration(const scene::Scene& scene) {
  float d = 0.0f;
  for (const auto& a : scene.animations) d = std::max(d, a.duration());
  return d;
}

// A camera that sees the whole playback (bounds sampled along it).
scene::Camera playbackCamera(const scene::Scene& scene) {
  const std::vector<int> all = scene::allAnimations(scene);
  scene::Bounds bounds;
  for (int s = 0; s <= 16; ++s) {
    const float t = duration(scene) * float(s) / 16.0f;
    bounds.extend(scene::posedWorldBounds(scene, scene::poseNodes(scene, all, t), scene::poseWeights(scene, all, t)));
  }
  return scene::frameBounds(bounds, float(kWidth) / float(kHeight));
}

gpu::HostImage renderAt(Session& session, scene::Scene& posed, const scene::Camera& camera, float t, uint32_t scale = 1) {
  poseAt(posed, session.renderer(), t);
  return session.renderer().render({.width = kWidth * scale, .height = kHeight * scale, .cameraOverride = camera}).image;
}

// MorphPrimitivesTest's texture (a fine UV grid with text) has no mipmaps
// (minFilter LINEAR): at 160x90 forward aliases it and decoupled, shading at
// shadel density, does not (29.6 dB). Twice the size keeps the comparison about the shading.
uint32_t renderScale(const std::string& name) { return name == "MorphPrimitivesTest" ? 2 : 1; }

void save(const std::string& name, const gpu::HostImage& image) {
  image::writePng(std::filesystem::temp_directory_path() / ("sg-animated-" + name + ".png"), image.width, image.height,
                  image.rgba8.data());
}

class AnimatedModels : public ::testing::TestWithParam<const char*> {};

TEST_P(AnimatedModels, TwoTimesInBothPathsAgree) {
  const std::string name = GetParam();
  if (!std::filesystem::exists(samplePath(name)))
    GTEST_SKIP() << "asset not found under " << assetsDir() << " (../shared/assets/gltf)";
  const scene::Scene loaded = scene::loadGltf(samplePath(name));
  bool deformable = false;
  for (const auto& mesh : loaded.meshes) deformable |= mesh.deformable();
  ASSERT_TRUE(deformable || !loaded.animations.empty()) << name << " is neither animated, skinned nor morphed";
  const scene::Camera camera = playbackCamera(loaded);
  // A quarter and half way: RiggedSimple's bend is symmetric about its middle (0.3 and 0.7 look alike).
  const float times[2] = {0.25f * duration(loaded), 0.5f * duration(loaded)};
  gpu::HostImage forward[2], decoupled[2];
  {
    Session f(loaded, scene::ShadingMode::Forward);
    scene::Scene posed = loaded;
    for (int k = 0; k < 2; ++k) forward[k] = renderAt(f, posed, camera, times[k], renderScale(name));
  }
  {
    Session d(loaded, scene::ShadingMode::Decoupled, {.storageChunks = 16384});
    scene::Scene posed = loaded;
    for (int k = 0; k < 2; ++k) {
      decoupled[k] = renderAt(d, posed, camera, times[k], renderScale(name));
      // Every object is decoupled, multi-primitive ones (MorphPrimitivesTest) too: one object per primitive.
      for (const auto& c : d.choices()) EXPECT_TRUE(c.decoupled) << name << " object " << c.instance << ": " << c.reason;
      EXPECT_GT(d.stats().objects, 0u) << name << ": nothing was shaded decoupled";
      if (k == 0)
        for (const auto& c : d.choices())
          std::printf("%-20s object %u: %s (%s)\n", name.c_str(), c.instance, c.decoupled ? "decoupled" : "forward",
                      c.reason.c_str());
      EXPECT_EQ(d.stats().counters.compositeMisses, 0u) << name << " t " << times[k];
    }
  }
  for (int k = 0; k < 2; ++k) {
    const auto diff = image::compareRgba8(forward[k].rgba8, decoupled[k].rgba8);
    std::printf("%-20s t %.2f s: decoupled vs forward PSNR %.2f dB\n", name.c_str(), double(times[k]), diff.psnr);
    EXPECT_GE(diff.psnr, 30.0) << name << " t " << times[k];
  }
  // The animation moves something on screen: the two times differ in each path.
  if (loaded.animations.empty()) return;  // MorphPrimitivesTest: static weights only
  // (At least 15 of the 14,400 pixels change by more than 8/255.)
  EXPECT_GT(image::compareRgba8(forward[0].rgba8, forward[1].rgba8).fractionAbove8, 0.001) << name << " forward";
  EXPECT_GT(image::compareRgba8(decoupled[0].rgba8, decoupled[1].rgba8).fractionAbove8, 0.001) << name << " decoupled";
  if (HasFailure() || std::getenv("SG_KEEP_RENDERS"))
    for (int k = 0; k < 2; ++k) {
      save(name + "-forward-" + std::to_string(k), forward[k]);
      save(name + "-decoupled-" + std::to_string(k), decoupled[k]);
    }
}

TEST_P(AnimatedModels, PlaybackHasNoMisses) {
  const std::string name = GetParam();
  if (!std::filesystem::exists(samplePath(name)))
    GTEST_SKIP() << "asset not found under " << assetsDir() << " (../shared/assets/gltf)";
  const scene::Scene loaded = scene::loadGltf(samplePath(name));
  const scene::Camera camera = playbackCamera(loaded);
  Session d(loaded, scene::ShadingMode::Decoupled, {.storageChunks = 16384});
  scene::Scene posed = loaded;
  uint64_t misses = 0, shaded = 0;
  for (int frame = 0; frame < 30; ++frame) {
    poseAt(posed, d.renderer(), duration(loaded) * float(frame) / 29.0f);
    d.renderer().render({.width = kWidth, .height = kHeight, .cameraOverride = camera, .readback = false});
    misses += d.stats().counters.compositeMisses;
    shaded += d.stats().objects;
  }
  if (std::any_of(d.choices().begin(), d.choices().end(), [](const auto& c) { return c.decoupled; })) {
    EXPECT_GT(shaded, 0u) << name;
  }
  EXPECT_EQ(misses, 0u) << name;
}

INSTANTIATE_TEST_SUITE_P(Models, AnimatedModels,
                         ::testing::Values("BoxAnimated", "InterpolationTest", "RiggedSimple", "RiggedFigure", "CesiumMan",
                                           "AnimatedMorphCube", "SimpleMorph", "MorphPrimitivesTest"),
                         [](const auto& param) { return std::string(param.param); });

// Frames in flight: the shade frame (layer shading on async compute, the
// frame's tail) reads frame N's deformed vertices while frame N+1's skinning
// pass rewrites them; the declared reads order the two (synchronization
// validation is on: a hazard fails the test).
TEST(AnimatedInFlight, ShadeFrameTailAndSkinningAreOrdered) {
  if (!std::filesystem::exists(samplePath("CesiumMan")))
    GTEST_SKIP() << "asset not found under " << assetsDir() << " (../shared/assets/gltf)";
  const scene::Scene loaded = scene::loadGltf(samplePath("CesiumMan"));
  const scene::Camera camera = playbackCamera(loaded);
  Session d(loaded, scene::ShadingMode::Decoupled, {.storageChunks = 16384, .shadeRate = 2, .overlap = true});
  scene::Scene posed = loaded;
  poseAt(posed, d.renderer(), 0.0f);
  const auto plan = d.renderer().plan({.width = kWidth, .height = kHeight, .cameraOverride = camera, .framesInFlight = 2});
  bool tailShades = false, skinningInTail = false;
  for (const auto& batch : plan.batches)
    for (const auto p : plan.passesOf(batch)) {
      tailShades |= batch.tail && plan.passes[p.index].name == "shade-frame layer-shade";
      skinningInTail |= batch.tail && plan.passes[p.index].name == "skinning";
    }
  EXPECT_TRUE(tailShades) << "the shade frame is the frame's tail";
  EXPECT_FALSE(skinningInTail);
  uint64_t misses = 0;
  for (int frame = 0; frame < 12; ++frame) {
    poseAt(posed, d.renderer(), 0.1f * float(frame));
    d.renderer().render({.width = kWidth, .height = kHeight, .cameraOverride = camera, .framesInFlight = 2,
                         .readback = frame == 11});
    misses += d.stats().counters.compositeMisses;
  }
  d.renderer().finishFrames();
  EXPECT_EQ(misses, 0u);
}

// The skinning pass's vertices against scene::deformVertex, read back from the scene vertex buffer.
TEST(GpuSkinning, MatchesTheCpuReference) {
  if (!std::filesystem::exists(samplePath("CesiumMan")) || !std::filesystem::exists(samplePath("SimpleMorph")))
    GTEST_SKIP() << "assets not found under " << assetsDir() << " (../shared/assets/gltf)";
  for (const char* name : {"CesiumMan", "SimpleMorph"}) {
    SCOPED_TRACE(name);
    const scene::Scene loaded = scene::loadGltf(samplePath(name));
    Session f(loaded, scene::ShadingMode::Forward);
    scene::Scene posed = loaded;
    const float t = 0.45f * duration(loaded);
    renderAt(f, posed, playbackCamera(loaded), t);
    f.renderer().finishFrames();
    const render::GpuScene& gpuScene = f.renderer().gpuScene();
    const gpu::Buffer& vertices = gpuScene.vertexStorage();
    gpu::Context& context = const_cast<gpu::Device&>(f.device()).context();
    gpu::Buffer readback(context, const_cast<gpu::Device&>(f.device()).memory(),
                         {vertices.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryLocation::Readback, "readback"});
    context.submitAndWait([&](VkCommandBuffer cmd) {
      const VkBufferCopy copy{0, 0, vertices.size()};
      vkCmdCopyBuffer(cmd, vertices.handle(), readback.handle(), 1, &copy);
    });
    const auto* gpuVertices = reinterpret_cast<const render::GpuVertex*>(readback.mapped());
    const auto& ranges = gpuScene.deformation().ranges();
    ASSERT_FALSE(ranges.empty());
    size_t checked = 0, vertexCount = 0;
    for (const render::DeformedRange& range : ranges) {
      const scene::Instance& instance = posed.instances[range.instance];
      const scene::Mesh& mesh = f.scene().meshes[size_t(instance.mesh)];
      // The range's primitive: the one of its mesh with as many vertices (these models have one each).
      const scene::Primitive* primitive = nullptr;
      for (const auto& p : mesh.primitives)
        if (p.vertexCount() == range.push.vertexCount) primitive = &p;
      ASSERT_NE(primitive, nullptr);
      std::vector<glm::mat4> joints;
      if (instance.skin >= 0)
        for (const glm::mat4& j : scene::jointWorldMatrices(posed.skins[size_t(instance.skin)],
                                                             scene::poseNodes(posed, scene::allAnimations(posed), t)))
          joints.push_back(glm::inverse(instance.world) * j);
      vertexCount += range.push.vertexCount;
      for (uint32_t v = 0; v < range.push.vertexCount; v += std::max(1u, range.push.vertexCount / 40)) {
        const scene::DeformedVertex cpu = scene::deformVertex(*primitive, v, joints, instance.morphWeights);
        const render::GpuVertex& gpu = gpuVertices[range.push.vertexFirst + v];
        const float scale = std::max(1.0f, glm::length(mesh.bounds.size()));
        EXPECT_LT(glm::length(gpu.position - cpu.position), 1e-4f * scale) << "vertex " << v;
        EXPECT_LT(glm::length(gpu.normal - cpu.normal), 1e-3f) << "vertex " << v;
        ++checked;
      }
      size_t moved = 0;
      for (uint32_t v = 0; v < range.push.vertexCount; ++v)
        moved += glm::length(gpuVertices[range.push.vertexFirst + v].position - primitive->positions[v]) > 1e-3f;
      EXPECT_GT(moved, 0u) << "posed, not at rest";
    }
    EXPECT_GE(checked, std::min<size_t>(20, vertexCount));
  }
}

}  // namespace
}  // namespace sg::test
