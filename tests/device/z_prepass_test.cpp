// The depth pre-pass only where it pays (passes/z-prepass/z_prepass_choice.hpp):
// a forward frame without it (forward-opaque writes the depth, occlusion-
// culled in two halves of its own) draws the image the frame with it draws,
// validation on; Auto measures the overdraw on its first frame and keeps it
// where the overdraw pays for it and drops it where it does not; frames with
// decoupled objects keep it whatever the setting.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <z-prepass/z_prepass_choice.hpp>

#include "decoupled_session.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kWidth = 160, kHeight = 120;

bool hasPass(const graph::CompiledPlan& plan, const std::string& name) {
  return std::any_of(plan.order.begin(), plan.order.end(),
                     [&](graph::PassId p) { return plan.passes[p.index].name == name; });
}

render::RenderSettings settings(render::ZPrepass zPrepass) {
  return {.width = kWidth, .height = kHeight, .zPrepass = zPrepass};
}

// One large-triangle scene (the courtyard) with a dense sphere of `segments`
// x segments/2 quads (2 triangles each) in front.
scene::Scene courtyardWithDenseSphere(uint32_t segments) {
  scene::Scene s = scene::makeDefaultScene(64);
  scene::Primitive sphere = scene::makeSphere(1.2f, segments, segments / 2);
  sphere.material = 0;
  scene::Mesh mesh{.name = "dense sphere", .bounds = sphere.bounds};
  mesh.primitives.push_back(std::move(sphere));
  s.meshes.push_back(std::move(mesh));
  s.instances.push_back({int(s.meshes.size() - 1), glm::translate(glm::mat4(1.0f), {0.0f, 1.5f, 1.0f}), "dense sphere",
                         scene::ShadingMode::Auto});
  return s;
}

// At 640x360: 230k pixels.
render::RenderSettings planned(render::ZPrepass zPrepass) { return {.width = 640, .height = 360, .zPrepass = zPrepass}; }

// The choice the z-prepass keeps, given to the session's renderer to read its report.
std::shared_ptr<passes::ZPrepassChoice> watchChoice(Session& session) {
  auto choice = std::make_shared<passes::ZPrepassChoice>();
  session.renderer().provideState(passes::kZPrepassChoiceState, choice);
  return choice;
}

// Auto: the first frame draws the pre-pass and counts the overdraw; the next
// ones keep it where the overdraw outweighs the triangles drawn again (the
// courtyard: 7k large triangles) and drop it where it does not (a sphere of
// 269k triangles in front, closed: little overdraw for its triangles).
TEST(ZPrepassRule, KeepsItWhereOverdrawPaysAndDropsItWhereItDoesNot) {
  Session sparse(scene::makeDefaultScene(64), scene::ShadingMode::Forward);
  const auto sparseChoice = watchChoice(sparse);
  EXPECT_TRUE(hasPass(sparse.renderer().plan(planned(render::ZPrepass::Auto)), "z-prepass")) << "nothing measured yet";
  sparse.renderer().render(planned(render::ZPrepass::Auto));
  const auto kept = sparse.renderer().plan(planned(render::ZPrepass::Auto));
  EXPECT_TRUE(hasPass(kept, "z-prepass"));
  EXPECT_TRUE(hasPass(kept, "z-prepass (late)"));
  EXPECT_FALSE(hasPass(kept, "forward-opaque (late)"));
  const auto& sparseReport = sparseChoice->collectedReport();
  ASSERT_TRUE(sparseReport.measured);
  EXPECT_FALSE(sparseReport.measuring);
  EXPECT_EQ(sparseReport.measurements, 1u) << "a frame only planned measures nothing";
  EXPECT_GT(sparseReport.measured->shaded, 0u);
  EXPECT_LE(sparseReport.measured->shaded, 640u * 360u) << "about one fragment a covered pixel";
  EXPECT_GT(sparseReport.measured->depthPassed, sparseReport.measured->shaded) << "the courtyard's overdraw";
  EXPECT_TRUE(passes::zPrepassPays(*sparseReport.measured));

  Session dense(courtyardWithDenseSphere(512), scene::ShadingMode::Forward);
  const auto denseChoice = watchChoice(dense);
  dense.renderer().render(planned(render::ZPrepass::Auto));
  const auto dropped = dense.renderer().plan(planned(render::ZPrepass::Auto));
  EXPECT_FALSE(hasPass(dropped, "z-prepass"));
  EXPECT_FALSE(hasPass(dropped, "z-prepass (late)"));
  EXPECT_TRUE(hasPass(dropped, "forward-opaque"));
  EXPECT_TRUE(hasPass(dropped, "forward-opaque (late)")) << "occlusion culling moves into forward-opaque";
  EXPECT_TRUE(hasPass(dropped, "occlusion-cull"));
  ASSERT_TRUE(denseChoice->collectedReport().measured);
  EXPECT_FALSE(denseChoice->collectedReport().drawn) << denseChoice->collectedReport().reason;
  // Another size: measured again, with the pre-pass.
  EXPECT_TRUE(hasPass(dense.renderer().plan({.width = 320, .height = 180}), "z-prepass"));
  EXPECT_TRUE(denseChoice->collectedReport().measuring);
  // Forced either way.
  EXPECT_TRUE(hasPass(dense.renderer().plan(planned(render::ZPrepass::On)), "z-prepass"));
  EXPECT_FALSE(hasPass(sparse.renderer().plan(planned(render::ZPrepass::Off)), "z-prepass"));
}

TEST(ZPrepassRule, FramesWithDecoupledObjectsKeepIt) {
  Session decoupled(courtyardWithDenseSphere(512), scene::ShadingMode::Decoupled);
  const auto plan = decoupled.renderer().plan(planned(render::ZPrepass::Off));
  EXPECT_TRUE(hasPass(plan, "z-prepass")) << "shadel-mark and composite test its depth";
  // The default bilinear filter: the z-prepass writes shadel-mark's requests, merged after it.
  EXPECT_TRUE(hasPass(plan, "shadel-mark-requests"));
  EXPECT_FALSE(hasPass(plan, "shadel-mark"));
  EXPECT_FALSE(hasPass(plan, "forward-opaque (late)"));
}

// A pass between z-prepass and forward-opaque that reads the depth (as the
// ssao plugin's does) keeps the pre-pass, whatever the setting: it reads depth
// the pre-pass drew (version above 0), not an unwritten image.
TEST(ZPrepassRule, APassReadingTheDepthBeforeForwardOpaqueKeepsIt) {
  plugin::Registry registry = plugins::builtinRegistry();
  uint32_t depthVersionRead = 0;
  registry.addPass({.name = "depth-reader",
                    .description = "reads the depth before forward-opaque",
                    .reads = {"scene.depth"},
                    .declare = [&](render::FrameContext& ctx) { depthVersionRead = ctx.read("scene.depth").version; }});
  registry.addFrame({.name = "depth-read", .base = "forward",
                     .passes = {{.pass = "depth-reader", .after = {"z-prepass"}, .before = {"forward-opaque"}}}});
  Session reading(courtyardWithDenseSphere(512), scene::ShadingMode::Forward, {}, registry, "depth-read");
  const auto plan = reading.renderer().plan(planned(render::ZPrepass::Off));
  EXPECT_TRUE(hasPass(plan, "z-prepass"));
  EXPECT_GT(depthVersionRead, 0u);
  Session plain(courtyardWithDenseSphere(512), scene::ShadingMode::Forward, {}, registry, "forward");
  EXPECT_FALSE(hasPass(plain.renderer().plan(planned(render::ZPrepass::Off)), "z-prepass"));
}

// 2CylinderEngine: 82 parts, one hiding another; frames 1 (nothing visible
// last frame: all drawn late) and 2 (last frame's visible drawn first).
TEST(ForwardWithoutZPrepass, SameImageAsWithItOnARealModel) {
  SG_REQUIRE_ASSETS();
  const scene::Scene model = scene::loadGltf(samplePath("2CylinderEngine"));
  Session with(model, scene::ShadingMode::Forward), without(model, scene::ShadingMode::Forward);
  for (int frame = 0; frame < 2; ++frame) {
    const auto a = with.renderer().render(settings(render::ZPrepass::On)).image;
    const auto b = without.renderer().render(settings(render::ZPrepass::Off)).image;
    const auto diff = image::compareRgba8(a.rgba8, b.rgba8);
    const double psnr = diff.psnr;
    // Depth written by the shaded draws instead of the pre-pass: only ties of
    // coplanar parts may resolve differently.
    EXPECT_GE(psnr, 50.0) << "frame " << frame;
    EXPECT_LE(diff.fractionAbove8, 0.001) << "frame " << frame << ": max |d| " << diff.maxAbs;
    std::printf("frame %d: PSNR %.2f dB, max |d| %d, mean |d| %.5f, %.5f%% of pixels by more than 8/255\n", frame,
                psnr, diff.maxAbs, diff.meanAbs, diff.fractionAbove8 * 100.0);
  }
}

}  // namespace
}  // namespace sg::test
