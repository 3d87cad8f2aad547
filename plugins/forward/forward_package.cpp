#include "forward_package.hpp"

#include <algorithm>
#include <limits>
#include <numbers>

#include <shadelgraph/render/frame_context.hpp>

#include "alpha-blend/alpha_blend.hpp"
#include "alpha-mask/alpha_mask.hpp"
#include "exposure/exposure.hpp"
#include "forward/forward.hpp"
#include "forward/forward_material.hpp"
#include "occlusion-cull/occlusion_cull.hpp"
#include "tonemap/tonemap.hpp"
#include "z-prepass/z_prepass.hpp"

namespace sg::plugins {
namespace {

using render::FrameContext;

// The z-prepass's default threshold (measured: see docs/benchmarks.md#occlusion-culling-and-the-depth-pre-pass).
constexpr double kMinOverdraw = 2.0;

graph::ResourceHandle depthTarget(FrameContext& ctx) {
  return ctx.has("scene.depth") ? ctx.read("scene.depth")
                                : ctx.graph().createImage("depth", {.format = graph::Format::D32F});
}

// This frame's draw commands, holding last frame's visibility, for the first
// of two halves of a culled pass (see occlusion_cull.hpp).
render::DrawCommands& importDrawCommands(FrameContext& ctx, render::DrawCulling& culling) {
  // Where the draw commands rest between frames: read as indirect arguments and written by the cull.
  const graph::ResourceState resting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                     graph::AccessFlag::IndirectCommandRead | graph::AccessFlag::ShaderStorageRead |
                                         graph::AccessFlag::ShaderStorageWrite};
  render::DrawCommands& commands = ctx.drawCommands();
  commands.handle = ctx.graph().importPersistentBuffer("draw commands", {.size = culling.commandBytes()}, resting);
  commands.buffer = culling.commands().handle();
  ctx.inputs().executor.bindBuffer(commands.handle, culling.commands());
  return commands;
}

// Culls against `depth` (holding the draws visible last frame); the passes
// declared after it draw only the visible draws. Returns the late draws.
graph::ResourceHandle cull(FrameContext& ctx, render::DrawCulling& culling, render::DrawCommands& commands,
                           graph::ResourceHandle depth) {
  const auto& in = ctx.inputs();
  const auto result =
      passes::addOcclusionCull(ctx.graph(), culling, in.viewProjection, in.width, in.height, depth, commands.handle);
  commands.handle = result.commands;
  return result.late;
}

// The depth pre-pass, occlusion-culled: the draws visible last frame first,
// then every draw tested against that depth, then the draws found visible
// that were not drawn yet.
graph::ResourceHandle culledZPrepass(FrameContext& ctx, render::DrawCulling& culling) {
  render::DrawCommands& commands = importDrawCommands(ctx, culling);
  const auto view = ctx.view(ctx.visibleDraws());
  const auto depth = passes::addZPrepass(ctx.graph(), view, depthTarget(ctx));
  return passes::addZPrepassLate(ctx.graph(), view, depth, cull(ctx, culling, commands, depth));
}

// Forward-opaque without a depth pre-pass: it writes the depth itself, culled in two halves like the pre-pass.
passes::ForwardTargets forwardOpaqueWritingDepth(FrameContext& ctx, passes::ForwardTargets t) {
  render::DrawCulling* culling = ctx.inputs().culling;
  if (!culling || ctx.draws().forward.size() < 2)
    return passes::addForwardOpaqueWritingDepth(ctx.graph(), ctx.view(ctx.draws().forward), t);
  render::DrawCommands& commands = importDrawCommands(ctx, *culling);
  const auto view = ctx.view(ctx.draws().forward);
  t = passes::addForwardOpaqueWritingDepth(ctx.graph(), view, t);
  return passes::addForwardOpaqueLate(ctx.graph(), view, t, cull(ctx, *culling, commands, t.depth));
}

// How many times over the opaque draws' bounding spheres cover the screen:
// the overdraw a depth pre-pass could save shading for, overestimated.
double estimatedOverdraw(FrameContext& ctx) {
  const auto& in = ctx.inputs();
  if (in.pixelsPerUnitAtUnitDistance <= 0.0f) return std::numeric_limits<double>::infinity();  // orthographic: unknown
  const double screen = double(in.width) * in.height;
  double covered = 0.0;
  const auto& draws = ctx.gpuScene().draws();
  for (uint32_t d : ctx.visibleDraws()) {
    if (draws[d].alphaMode != scene::AlphaMode::Opaque) continue;
    const glm::vec4 sphere = in.drawSpheres[d];
    const double distance = glm::distance(glm::vec3(sphere), in.cameraPosition);
    const double radius = sphere.w * in.pixelsPerUnitAtUnitDistance / std::max(distance - sphere.w, 1e-6);
    covered += distance <= sphere.w ? screen : std::min(screen, std::numbers::pi * radius * radius);
  }
  return covered / screen;
}

passes::ForwardTargets targets(FrameContext& ctx) { return {ctx.read("scene.hdr"), ctx.read("scene.depth")}; }

void publish(FrameContext& ctx, const passes::ForwardTargets& t) {
  ctx.write("scene.hdr", t.color);
  ctx.write("scene.depth", t.depth);
}

}  // namespace

void registerForwardPackage(plugin::Registry& registry) {
  registry.addPass({.name = "z-prepass",
                    .description = "depth of every visible opaque object, forward or decoupled (in a frame "
                                   "without decoupled objects only when their overdraw is worth it; forward-opaque "
                                   "then writes the depth)",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {"scene.depth"},
                    .parameters = {{"min-overdraw", kMinOverdraw,
                                    "without decoupled objects, run only when the opaque objects' bounding spheres "
                                    "cover the screen this many times over (0: always)"}},
                    .declare = [](FrameContext& ctx) {
                      // shadel-mark needs the depth first; forward shading alone pays for a
                      // pre-pass (all geometry once more) only with enough overdraw.
                      if (ctx.draws().decoupled.empty() &&
                          estimatedOverdraw(ctx) < ctx.parameter<double>("min-overdraw")) {
                        ctx.write("scene.depth", depthTarget(ctx));
                        return;
                      }
                      // One draw has nothing to hide behind.
                      if (ctx.inputs().culling && ctx.visibleDraws().size() > 1) {
                        ctx.write("scene.depth", culledZPrepass(ctx, *ctx.inputs().culling));
                        return;
                      }
                      ctx.write("scene.depth",
                                passes::addZPrepass(ctx.graph(), ctx.view(ctx.visibleDraws()), depthTarget(ctx)));
                    }});
  registry.addPass({.name = "forward-opaque",
                    .description = "opaque objects shaded forward (their material's fragment variant); clears the HDR colour",
                    .reads = {plugin::kForwardDrawsResource, "scene.depth"},
                    .writes = {"scene.hdr", "scene.depth"},
                    .declare = [](FrameContext& ctx) {
                      const passes::ForwardTargets t{ctx.graph().createImage("hdr", {.format = graph::Format::RGBA16F}),
                                                     ctx.read("scene.depth")};
                      // A depth nothing wrote yet (the pre-pass did not run): draw it here.
                      const bool depthWritten = t.depth.version > 0 ||
                                                ctx.graph().resource(t.depth.id).kind != graph::ResourceKind::TransientImage;
                      publish(ctx, depthWritten ? passes::addForwardOpaque(ctx.graph(), ctx.view(ctx.draws().forward), t)
                                                : forwardOpaqueWritingDepth(ctx, t));
                    }});
  registry.addPass({.name = "alpha-mask",
                    .description = "alpha-tested objects (only when a visible object has such a material)",
                    .reads = {plugin::kForwardDrawsResource, "scene.hdr", "scene.depth"},
                    .writes = {"scene.hdr", "scene.depth"},
                    .declare = [](FrameContext& ctx) {
                      const auto view = ctx.view(ctx.draws().forward);
                      if (passes::hasAlphaMode(view, scene::AlphaMode::Mask))
                        publish(ctx, passes::addAlphaMask(ctx.graph(), view, targets(ctx)));
                    }});
  registry.addPass({.name = "alpha-blend",
                    .description = "blended objects back to front (only when a visible object has such a material)",
                    .reads = {plugin::kForwardDrawsResource, "scene.hdr", "scene.depth"},
                    .writes = {"scene.hdr"},
                    .declare = [](FrameContext& ctx) {
                      const auto view = ctx.view(ctx.draws().forward);
                      if (passes::hasAlphaMode(view, scene::AlphaMode::Blend))
                        ctx.write("scene.hdr", passes::addAlphaBlend(ctx.graph(), view, ctx.inputs().cameraPosition,
                                                                     targets(ctx)));
                    }});
  registry.addPass({.name = "exposure",
                    .description = "automatic exposure from the log-average luminance (async compute)",
                    .queue = graph::QueueClass::AsyncCompute,
                    .reads = {"scene.hdr"},
                    .writes = {"scene.exposure"},
                    .declare = [](FrameContext& ctx) {
                      ctx.write("scene.exposure", passes::addExposure(ctx.graph(), ctx.read("scene.hdr")));
                    }});
  registry.addPass({.name = "tonemap",
                    .description = "HDR colour, exposed, to the 8-bit sRGB output",
                    .reads = {"scene.hdr", "scene.exposure", plugin::kOutputResource},
                    .writes = {plugin::kOutputResource},
                    .declare = [](FrameContext& ctx) {
                      ctx.write(plugin::kOutputResource,
                                passes::addTonemap(ctx.graph(), ctx.read("scene.hdr"), ctx.read("scene.exposure"),
                                                   ctx.read(plugin::kOutputResource), ctx.debugColors));
                    }});
  registry.addFrame({.name = "forward",
                     .passes = {{.pass = "z-prepass"}, {.pass = "forward-opaque"}, {.pass = "alpha-mask"},
                                {.pass = "alpha-blend"}, {.pass = "exposure"}, {.pass = "tonemap"}}});
}

}  // namespace sg::plugins
