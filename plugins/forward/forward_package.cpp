#include "forward_package.hpp"

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

graph::ResourceHandle depthTarget(FrameContext& ctx) {
  return ctx.has("scene.depth") ? ctx.read("scene.depth")
                                : ctx.graph().createImage("depth", {.format = graph::Format::D32F});
}

// The depth pre-pass, occlusion-culled: the draws visible last frame first,
// then every draw tested against that depth, then the draws found visible
// that were not drawn yet. The passes after it draw only the visible ones.
graph::ResourceHandle culledZPrepass(FrameContext& ctx, render::DrawCulling& culling) {
  // Where the draw commands rest between frames: read as indirect arguments and written by the cull.
  const graph::ResourceState resting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                     graph::AccessFlag::IndirectCommandRead | graph::AccessFlag::ShaderStorageRead |
                                         graph::AccessFlag::ShaderStorageWrite};
  const auto& in = ctx.inputs();
  render::DrawCommands& commands = ctx.drawCommands();
  commands.handle = ctx.graph().importPersistentBuffer("draw commands", {.size = culling.commandBytes()}, resting);
  commands.buffer = culling.commands().handle();
  in.executor.bindBuffer(commands.handle, culling.commands());
  const auto view = ctx.view(ctx.visibleDraws());
  auto depth = passes::addZPrepass(ctx.graph(), view, depthTarget(ctx));
  const auto cull = passes::addOcclusionCull(ctx.graph(), culling, in.viewProjection, in.width, in.height, depth,
                                             commands.handle);
  commands.handle = cull.commands;
  return passes::addZPrepassLate(ctx.graph(), view, depth, cull.late);
}

passes::ForwardTargets targets(FrameContext& ctx) { return {ctx.read("scene.hdr"), ctx.read("scene.depth")}; }

void publish(FrameContext& ctx, const passes::ForwardTargets& t) {
  ctx.write("scene.hdr", t.color);
  ctx.write("scene.depth", t.depth);
}

}  // namespace

void registerForwardPackage(plugin::Registry& registry) {
  registry.addPass({.name = "z-prepass",
                    .description = "depth of every visible opaque object, forward or decoupled",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {"scene.depth"},
                    .declare = [](FrameContext& ctx) {
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
                      publish(ctx, passes::addForwardOpaque(ctx.graph(), ctx.view(ctx.draws().forward), t));
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
