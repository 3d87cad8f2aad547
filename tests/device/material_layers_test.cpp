// Material layers on the device, validation on: each built-in stack renders
// decoupled and forward from its one source and the two agree; neighbourhood
// layers get support-expand, persistent layers reuse last frame, and a frame
// holds only the passes, dispatches and history its visible materials need.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/image/png.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 192;

// 512-texel textures: level 0 follows the textures' density, and the
// procedural layers (marble, bumps) need it at least this fine.
scene::Scene courtyardWith(const std::string& material) {
  scene::Scene s = scene::makeDefaultScene(512);
  for (auto& instance : s.instances) instance.material = material;
  return s;
}

bool hasPass(const graph::CompiledPlan& plan, const std::string& name) {
  return std::any_of(plan.order.begin(), plan.order.end(),
                     [&](graph::PassId p) { return plan.passes[p.index].name == name; });
}

size_t historyResources(const graph::CompiledPlan& plan) {
  return size_t(std::count_if(plan.resources.begin(), plan.resources.end(), [](const graph::PlannedResource& r) {
    return r.kind == graph::ResourceKind::History && !r.culled;
  }));
}

image::ImageDifference renderBothWays(const std::string& material) {
  Session decoupled(courtyardWith(material), scene::ShadingMode::Decoupled);
  Session forward(courtyardWith(material), scene::ShadingMode::Forward);
  const auto a = decoupled.render(kSize), b = forward.render(kSize);
  if (const char* dir = std::getenv("SG_TEST_IMAGES")) {  // to look at them
    image::writePng(std::string(dir) + "/" + material + "-decoupled.png", a.width, a.height, a.rgba8.data());
    image::writePng(std::string(dir) + "/" + material + "-forward.png", b.width, b.height, b.rgba8.data());
  }
  const auto c = decoupled.stats().counters;
  std::printf("%s: marked %u (support %u), allocated %u, overflow %u, capacity %u\n", material.c_str(), c.chunksMarked,
              c.supportChunks, c.chunksAllocated, c.overflowChunks, decoupled.stats().capacityChunks);
  EXPECT_EQ(decoupled.stats().counters.compositeMisses, 0u);
  const auto d = image::compareRgba8(a.rgba8, b.rgba8);
  std::printf("%-18s decoupled vs forward: PSNR %.2f dB, mean |d| %.2f/255, %.2f%% pixels > 8/255\n",
              material.c_str(), d.psnr, d.meanAbs, 100.0 * d.fractionAbove8);
  return d;
}

// A copy of the first object, 20 units behind the scene's camera.
void addBehindTheCamera(scene::Scene& s) {
  const scene::Camera camera = s.cameras.front();
  s.instances.push_back(s.instances.front());
  s.instances.back().world = glm::translate(glm::mat4(1.0f), glm::vec3(camera.world[2]) * 20.0f) *
                             glm::translate(glm::mat4(1.0f), glm::vec3(camera.world[3]));
}

// High-frequency energy: mean absolute difference between horizontal neighbours.
double roughness(const gpu::HostImage& image) {
  double sum = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 1; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        sum += std::abs(int(image.rgba8[(y * image.width + x) * 4 + c]) -
                        int(image.rgba8[(y * image.width + x - 1) * 4 + c]));
  return sum / (image.width * image.height * 3.0);
}

TEST(MaterialLayers, GltfPbrNeedsOneDispatchPerObjectAndNothingElse) {
  Session d(courtyardWith("gltf-pbr"), scene::ShadingMode::Decoupled);
  const auto plan = d.plan(kSize);
  EXPECT_TRUE(hasPass(plan, "layer-shade"));
  EXPECT_FALSE(hasPass(plan, "layer-shade #2"));
  EXPECT_FALSE(hasPass(plan, "support-expand")) << "no layer reads a neighbourhood";
  EXPECT_EQ(historyResources(plan), 0u) << "no layer persists";
  d.render(kSize);
  const auto s = d.stats();
  EXPECT_GT(s.objects, 0u);
  EXPECT_EQ(s.layerDispatches, s.objects);
  EXPECT_EQ(s.historyBytes, 0u);
  EXPECT_EQ(s.counters.supportChunks, 0u);
  EXPECT_EQ(s.layers, std::vector<std::string>{"gltf-pbr"});
}

TEST(MaterialLayers, BumpsHeightToNormalAgreesWithItsForwardFallback) {
  Session d(courtyardWith("bumps"), scene::ShadingMode::Decoupled);
  EXPECT_TRUE(hasPass(d.plan(kSize), "support-expand"));
  const auto bumped = d.render(kSize);
  EXPECT_GT(d.stats().counters.supportChunks, 0u) << "radius-1 reads need the chunks around the visible ones";
  EXPECT_EQ(d.stats().layerDispatches, 2 * d.stats().objects);
  // Visibly different from the flat material, and the two variants agree.
  Session flat(courtyardWith("gltf-pbr"), scene::ShadingMode::Decoupled);
  EXPECT_GT(image::compareRgba8(bumped.rgba8, flat.render(kSize).rgba8).meanAbs, 1.0);
  const auto both = renderBothWays("bumps");
  EXPECT_GT(both.psnr, 26.0);
  EXPECT_LT(both.meanAbs, 6.0);
}

TEST(MaterialLayers, SkinBlurCostsThreeDispatchesPerObjectAndSmooths) {
  Session skin(courtyardWith("skin"), scene::ShadingMode::Decoupled);
  const auto plan = skin.plan(kSize);
  for (const char* pass : {"layer-shade", "layer-shade #2", "layer-shade #3", "support-expand"})
    EXPECT_TRUE(hasPass(plan, pass)) << pass;
  EXPECT_FALSE(hasPass(plan, "layer-shade #4"));
  const auto blurred = skin.render(kSize);
  const auto s = skin.stats();
  EXPECT_EQ(s.layerDispatches, 3 * s.objects) << "three layers: three dispatches per visible object, not more";
  EXPECT_EQ(s.layers, (std::vector<std::string>{"gltf-pbr", "blur-u", "blur-v"}));
  EXPECT_EQ(s.counters.compositeMisses, 0u);
  Session sharp(courtyardWith("gltf-pbr"), scene::ShadingMode::Decoupled);
  const double sharpRoughness = roughness(sharp.render(kSize)), blurredRoughness = roughness(blurred);
  std::printf("neighbour difference: gltf-pbr %.3f, skin %.3f\n", sharpRoughness, blurredRoughness);
  EXPECT_LT(blurredRoughness, 0.9 * sharpRoughness);
}

// Shadel masks (issue 14) shade only the shadels composite reads, except for
// objects whose material reads a neighbourhood: their chunks (support-expand's
// ring included) are shaded whole, or the blur would read unshaded shadels.
// Half the objects skin, half gltf-pbr: the same image as whole chunks everywhere.
TEST(MaterialLayers, ShadelMasksShadeNeighbourhoodReadersWhole) {
  scene::Scene mixed = courtyardWith("skin");
  for (size_t i = 0; i < mixed.instances.size(); i += 2) mixed.instances[i].material = "gltf-pbr";
  Session masked(mixed, scene::ShadingMode::Decoupled), whole(mixed, scene::ShadingMode::Decoupled, {.shadelMasks = false});
  const auto a = masked.render(kSize), b = whole.render(kSize);
  EXPECT_TRUE(a.rgba8 == b.rgba8) << "an unshaded shadel was read";
  EXPECT_GT(masked.stats().counters.supportChunks, 0u);
  EXPECT_GT(masked.stats().counters.shadelsSkipped, 0u) << "the gltf-pbr objects' chunks are masked";
  EXPECT_EQ(whole.stats().counters.shadelsSkipped, 0u);
}

// A layer-shade workgroup is one subgroup (passes::chunkRowsPerInvocation):
// 8 invocations of 8 rows on lavapipe, 32 or 64 of 2 or 1 on a GPU. Every
// shape shades the same shadels, so the images and counters are the same:
// masked gltf-pbr, neighbour-reading skin, and marble reused in a second frame.
TEST(MaterialLayers, EveryLayerShadeWorkgroupShapeShadesTheSameImage) {
  // Shadel masks need a frame without persistent layers: masked gltf-pbr and
  // neighbour-reading skin in one scene, marble (kept from frame to frame) in another.
  scene::Scene masked = courtyardWith("skin");
  for (size_t i = 0; i < masked.instances.size(); i += 2) masked.instances[i].material = "gltf-pbr";
  struct Shape {
    std::vector<uint8_t> masked, marble;
    uint32_t skipped = 0;
    uint64_t reused = 0, computed = 0;
  };
  std::vector<Shape> shapes;
  for (const uint32_t invocations : {8u, 16u, 32u, 64u}) {
    SCOPED_TRACE("invocations " + std::to_string(invocations));
    Shape& shape = shapes.emplace_back();
    Session m(masked, scene::ShadingMode::Decoupled, {.layerShadeInvocations = invocations});
    shape.masked = m.render(kSize).rgba8;
    shape.skipped = m.stats().counters.shadelsSkipped;
    EXPECT_GT(shape.skipped, 0u) << "gltf-pbr's chunks are masked";
    EXPECT_EQ(m.stats().counters.compositeMisses, 0u);
    Session marble(courtyardWith("marble"), scene::ShadingMode::Decoupled,
                   {.layerShadeInvocations = invocations, .fixedBias = 0.0f});
    marble.render(kSize);
    shape.marble = marble.render(kSize).rgba8;
    ASSERT_EQ(marble.stats().layerReuse.size(), 1u);
    shape.reused = marble.stats().layerReuse[0].reused;
    shape.computed = marble.stats().layerReuse[0].computed;
    EXPECT_GT(shape.reused, 0u) << "marble kept from the first frame";
  }
  for (size_t i = 1; i < shapes.size(); ++i) {
    SCOPED_TRACE("shape " + std::to_string(i) + " against 8 invocations");
    EXPECT_TRUE(shapes[i].masked == shapes[0].masked) << "a shape shaded other shadels";
    EXPECT_TRUE(shapes[i].marble == shapes[0].marble) << "a shape reused other shadels";
    EXPECT_EQ(shapes[i].skipped, shapes[0].skipped);
    EXPECT_EQ(shapes[i].reused, shapes[0].reused);
    EXPECT_EQ(shapes[i].computed, shapes[0].computed);
  }
}

TEST(MaterialLayers, MarbleIsReusedFromLastFrame) {
  Session d(courtyardWith("marble"), scene::ShadingMode::Decoupled, {.fixedBias = 0.0f});
  EXPECT_EQ(historyResources(d.plan(kSize)), 1u)
      << "last frame's marble image (where it stored a shadel is where it is now: stable allocation)";
  const auto first = d.render(kSize);
  const auto s1 = d.stats();
  ASSERT_EQ(s1.layerReuse.size(), 1u);
  EXPECT_EQ(s1.layerReuse[0].layer, "marble");
  EXPECT_EQ(s1.layerReuse[0].reused, 0u) << "nothing to reuse in the first frame";
  EXPECT_GT(s1.layerReuse[0].computed, 0u);
  EXPECT_GT(s1.historyBytes, 0u);
  const auto second = d.render(kSize);
  const auto s2 = d.stats();
  const double reuse = double(s2.layerReuse[0].reused) / double(s2.layerReuse[0].reused + s2.layerReuse[0].computed);
  EXPECT_GT(reuse, 0.95) << "the same view: every shadel existed last frame";
  const auto same = image::compareRgba8(first.rgba8, second.rgba8);
  EXPECT_LT(same.maxAbs, 2) << "a reused value is the value";
  // A moved camera: some shadels are new, most are not.
  scene::Camera moved = scene::makeDefaultScene(16).cameras.front();
  moved.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.15f, 0.0f, 0.0f)) * moved.world;
  d.render(kSize, moved);
  const auto s3 = d.stats();
  EXPECT_GT(s3.layerReuse[0].computed, 0u);
  EXPECT_GT(s3.layerReuse[0].reused, 0u);
  // The marble is band-limited by each sample's footprint; where the shadels
  // are coarser than the pixels (the box walls' stretched chart: a wall shadel
  // is several pixels wide) the decoupled marble is the smoother one.
  const auto both = renderBothWays("marble");
  EXPECT_GT(both.psnr, 22.0);
}

TEST(MaterialLayers, DebugLayersRenderInBothPaths) {
  for (const char* material : {"debug-uv-checker", "debug-triangle-id", "debug-detail-level"}) {
    SCOPED_TRACE(material);
    const auto both = renderBothWays(material);
    // detail-level differs by design: the shadel's level against a level derived from pixel derivatives.
    if (std::string(material) != "debug-detail-level") {
      EXPECT_GT(both.psnr, 20.0);
    }
  }
}

// Does the device hold the layer-shade pipeline of `layer`, in any workgroup
// shape (rows per invocation: layer_shade.cpp)?
bool hasLayerPipeline(const gpu::Device& device, const std::string& layer) {
  for (const uint32_t rows : {1u, 2u, 4u, 8u})
    if (device.hasPipeline("layer-shade/" + layer + "/rows" + std::to_string(rows))) return true;
  return false;
}

TEST(MaterialLayers, HiddenObjectsBringNoLayers) {
  // The marble object is behind the camera: its persistent layer and history
  // must not appear, the others' gltf-pbr must.
  scene::Scene s = courtyardWith("gltf-pbr");
  addBehindTheCamera(s);
  s.instances.back().material = "marble";
  Session d(std::move(s), scene::ShadingMode::Decoupled);
  EXPECT_EQ(historyResources(d.plan(kSize)), 0u);
  d.render(kSize);
  EXPECT_EQ(d.stats().layers, std::vector<std::string>{"gltf-pbr"});
  EXPECT_EQ(d.stats().historyBytes, 0u);
  EXPECT_TRUE(hasLayerPipeline(d.device(), "gltf-pbr"));
  EXPECT_FALSE(hasLayerPipeline(d.device(), "marble")) << "compiled only for visible objects' materials";
  EXPECT_FALSE(hasLayerPipeline(d.device(), "marble-shade"));
}

// Does the device hold a forward pipeline of `material`, in any variant (plain
// or not, any of the frame features compiled out: forward_material.cpp)?
bool hasForwardPipeline(const gpu::Device& device, const std::string& material) {
  for (const char* plain : {"", "plain/"})
    for (const char* shadows : {"", "no-shadows/"})
      for (const char* grid : {"", "no-grid/"})
        for (const char* env : {"", "no-env/"})
          if (device.hasPipeline(std::string("forward/") + plain + shadows + grid + env + material)) return true;
  return false;
}

TEST(MaterialLayers, HiddenForwardObjectsCompileNothing) {
  scene::Scene s = courtyardWith("gltf-pbr");
  addBehindTheCamera(s);
  s.instances.back().material = "debug-uv-checker";
  Session d(std::move(s), scene::ShadingMode::Forward);
  d.render(kSize);
  EXPECT_TRUE(hasForwardPipeline(d.device(), "gltf-pbr"));
  EXPECT_FALSE(hasForwardPipeline(d.device(), "debug-uv-checker")) << "the only object with it is behind the camera";
}

// A layer's own texture (a PNG it declares), in both paths.
TEST(MaterialLayers, LayerTexturesAreBoundInBothPaths) {
  test::TempDir dir;
  std::vector<uint8_t> red(8 * 8 * 4);
  for (size_t i = 0; i < red.size(); i += 4) {
    red[i] = 220;
    red[i + 1] = 40;
    red[i + 2] = 30;
    red[i + 3] = 255;
  }
  image::writePng(dir.path() / "tint.png", 8, 8, red.data());
  std::filesystem::create_directories(dir.path() / "tinted");
  std::ofstream(dir.path() / "tinted" / "tinted.glsl") << "vec4 tinted(Surface s) {\n"
                                                           "  return textureGrad(tint, s.uv0, s.uv0Dx, s.uv0Dy);\n"
                                                           "}\n";
  plugin::Registry registry;
  plugins::registerBuiltins(registry);
  registry.beginPlugin("test");
  registry.addShaderDirectory(dir.path());
  registry.addLayer({.name = "tinted", .source = "tinted/tinted.glsl", .function = "tinted",
                     .textures = {{.name = "tint", .file = dir.path() / "tint.png"}}});
  registry.addMaterial({.name = "tinted", .layers = {"tinted"}});
  for (const auto mode : {scene::ShadingMode::Decoupled, scene::ShadingMode::Forward}) {
    Session d(courtyardWith("tinted"), mode, {}, registry);
    const auto image = d.render(64);
    // Unlit texture colour everywhere but the sky: the exposure scales it, the hue stays.
    const uint8_t* p = &image.rgba8[(48 * 64 + 32) * 4];
    EXPECT_GT(p[0], 2 * p[1]) << "mode " << int(mode);
    EXPECT_GT(p[0], 2 * p[2]) << "mode " << int(mode);
  }
}

TEST(MaterialLayers, MissingLayerTextureIsAClearError) {
  plugin::Registry registry;
  plugins::registerBuiltins(registry);
  registry.beginPlugin("test");
  registry.addLayer({.name = "lost", .source = "x.glsl", .function = "f",
                     .textures = {{.name = "gone", .file = "/nonexistent/gone.png"}}});
  registry.addMaterial({.name = "lost", .layers = {"lost"}});
  try {
    registry.check();
    FAIL() << "accepted";
  } catch (const plugin::PluginError& e) {
    EXPECT_NE(std::string(e.what()).find("texture 'gone': no such file /nonexistent/gone.png"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sg::test
