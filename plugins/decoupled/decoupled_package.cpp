#include "decoupled_package.hpp"

#include <shadelgraph/render/frame_context.hpp>

#include "composite/composite.hpp"
#include "debug-views/debug_views.hpp"
#include "forward/forward.hpp"
#include "shadel-allocate/shadel_allocate.hpp"
#include "shadel-clear/shadel_clear.hpp"
#include "shadel-mark/shadel_mark.hpp"
#include "support-expand/support_expand.hpp"
#include "work-aggregate/work_aggregate.hpp"

namespace sg::plugins {
namespace {

using render::FrameContext;

DecoupledShading& shading(FrameContext& ctx) { return ctx.state<DecoupledShading>(kDecoupledState); }

// Every decoupled pass prepares the frame's shared state (once per frame), so
// a frame may hold any subset of them.
void prepare(FrameContext& ctx) { shading(ctx).prepare(ctx); }

// A pass that runs only while some object is decoupled this frame.
plugin::PassPlugin shadingPass(std::string name, std::string description, graph::QueueClass queue,
                               std::vector<std::string> reads, std::vector<std::string> writes,
                               void (*add)(graph::RenderGraph&, passes::DecoupledFrame&)) {
  return {.name = std::move(name),
          .description = std::move(description),
          .queue = queue,
          .reads = reads,
          .writes = writes,
          .prepare = prepare,
          .declare = [add, writes](FrameContext& ctx) {
            DecoupledShading& d = shading(ctx);
            if (!d.shading()) return;
            add(ctx.graph(), d.frame(ctx));
            for (const auto& w : writes) d.publish(ctx, {w.c_str()});
          }};
}

}  // namespace

void registerDecoupledPackage(plugin::Registry& registry) {
  registry.addPass({.name = "shadel-clear",
                    .description = "resets the occupancy of remap entries owned by allocated objects, the shade "
                                   "counters and the work counts",
                    .queue = graph::QueueClass::Graphics,
                    .reads = {plugin::kDecoupledDrawsResource},
                    .writes = {"shadel.remap", "shadel.counters", "shadel.work"},
                    .prepare = prepare,
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      // With objects allocated but none shaded this frame, the counters are
                      // still cleared and read back (the adjuster and stats see a zero frame).
                      if (!d.hasObjects()) return;
                      d.addLiveEntryBlocks(ctx);
                      passes::addShadelClear(ctx.graph(), d.frame(ctx));
                      d.publish(ctx, {"shadel.remap", "shadel.counters", "shadel.work"});
                    }});
  registry.addPass({.name = "shadel-mark",
                    .description = "marks the chunks composite will read: from the requests the depth pre-pass wrote (bilinear), "
                                   "else rasterizing decoupled objects against the depth",
                    // view.decoupled: it draws only decoupled objects (a frame without them may skip the z-prepass).
                    .reads = {"scene.depth", "shadel.remap", plugin::kDecoupledDrawsResource},
                    .writes = {"shadel.remap"},
                    .prepare = prepare,
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      if (!d.shading()) return;
                      d.takeMarkRequests(ctx);
                      passes::addShadelMark(ctx.graph(), d.frame(ctx), ctx.read("scene.depth"));
                      d.publish(ctx, {"shadel.remap"});
                    }});
  registry.addPass({.name = "support-expand",
                    .description = "marks the chunks around marked ones (only when a visible material reads a neighbourhood)",
                    .reads = {"shadel.remap", "shadel.counters"},
                    .writes = {"shadel.remap", "shadel.counters"},
                    .prepare = prepare,
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      if (!d.shading() || !d.needsSupport()) return;
                      passes::addSupportExpand(ctx.graph(), d.frame(ctx));
                      d.publish(ctx, {"shadel.remap", "shadel.counters"});
                    }});
  registry.addPass(shadingPass("shadel-allocate", "storage for every marked chunk from hashed partitions (async compute)",
                               graph::QueueClass::AsyncCompute, {"shadel.remap", "shadel.counters", "shadel.work"},
                               {"shadel.remap", "shadel.counters", "shadel.work"}, passes::addShadelAllocate));
  registry.addPass(shadingPass("work-aggregate",
                               "per object the chunks to shade and one indirect dispatch (async compute)",
                               graph::QueueClass::AsyncCompute, {"shadel.remap", "shadel.counters", "shadel.work"},
                               {"shadel.work", "shadel.args", "shadel.counters"}, passes::addWorkAggregate));
  registry.addPass({.name = "layer-shade",
                    .description = "material layers over the chunks to shade, one pass per layer depth (async compute)",
                    .queue = graph::QueueClass::AsyncCompute,
                    .reads = {"shadel.remap", "shadel.work", "shadel.args", "shadel.counters"},
                    .writes = {"shadel.shaded", "shadel.counters"},
                    .prepare = prepare,
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      if (!d.shading()) return;
                      d.frame(ctx);
                      d.addLayerPasses(ctx.graph(), ctx.registry());
                      d.publish(ctx, {"shadel.shaded", "shadel.counters"});
                    }});
  registry.addPass({.name = "composite",
                    .description = "draws decoupled objects filtering their shaded samples through the remap table",
                    .reads = {"scene.hdr", "scene.depth", "shadel.shaded", "shadel.remap", "shadel.counters"},
                    // shadel.shaded: its shadel-gutter step fills the tiles' gutters first;
                    // scene.depth: of fragments tied in depth it draws the first (composite.hpp).
                    .writes = {"scene.hdr", "scene.depth", "shadel.shaded", "shadel.counters"},
                    .parameters = {{"filter", -1, "0 point, 1 bilinear, 2 trilinear; -1: the renderer's setting"}},
                    // The filter is settled here, before any pass declares: shadel-mark
                    // marks the footprint of the same filter.
                    .prepare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      d.prepare(ctx);
                      const int filter = ctx.parameter<int>("filter");
                      if (filter > 2)
                        throw plugin::FrameError("pass 'composite': filter " + std::to_string(filter) +
                                                 " (0 point, 1 bilinear, 2 trilinear)");
                      if (filter >= 0) d.setFrameFilter(ctx, filter);
                    },
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      if (!d.shading()) return;
                      passes::DecoupledFrame& frame = d.frame(ctx);
                      const auto hdr = ctx.read("scene.hdr");
                      const auto out = passes::addComposite(
                          ctx.graph(), frame, hdr, ctx.read("scene.depth"),
                          passes::clearIfUnwritten(hdr, passes::hdrBackground(ctx.inputs().scene.lights)));
                      ctx.write("scene.hdr", out.color);
                      ctx.write("scene.depth", out.depth);
                      d.publish(ctx, {"shadel.shaded", "shadel.counters"});
                    }});
  registry.addPass({.name = "counters-readback",
                    .description = "copies the shade counters for the adjuster and the stats (read a frame later)",
                    .queue = graph::QueueClass::Graphics,
                    .reads = {"shadel.counters"},
                    .prepare = prepare,
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      if (!d.hasObjects()) return;
                      d.frame(ctx);
                      d.addCountersReadback(ctx.graph());
                      d.addShadeFrameTail(ctx.graph(), ctx.registry());
                    }});
  registry.addPass({.name = "decoupled-debug-view",
                    .description = "with --view level|occupancy|sheet: replaces the colour with a view of decoupled shading",
                    .reads = {"scene.hdr", "shadel.remap", "shadel.shaded"},
                    .writes = {"scene.hdr"},
                    .prepare = prepare,
                    .declare = [](FrameContext& ctx) {
                      DecoupledShading& d = shading(ctx);
                      const DebugView view = d.settings().view;
                      ctx.debugColors = view != DebugView::Final;
                      if (!d.shading()) return;
                      if (view == DebugView::Occupancy)
                        ctx.write("scene.hdr", passes::addOccupancyView(ctx.graph(), d.frame(ctx), d.sheetRegionOrigin(),
                                                                        d.sheetRegionSize()));
                      if (view == DebugView::Sheet) ctx.write("scene.hdr", passes::addSheetView(ctx.graph(), d.frame(ctx)));
                    }});
  registry.addFrame({.name = "decoupled",
                     .passes = {{.pass = "skinning"}, {.pass = "z-prepass"}, {.pass = "object-pick"}, {.pass = "shadows"}, {.pass = "environment"}, {.pass = "light-cull"},
                                {.pass = "shadel-clear"}, {.pass = "shadel-mark"},
                                {.pass = "support-expand"}, {.pass = "shadel-allocate"}, {.pass = "work-aggregate"},
                                {.pass = "layer-shade"}, {.pass = "forward-opaque"}, {.pass = "alpha-mask"},
                                {.pass = "composite"}, {.pass = "environment-background"}, {.pass = "counters-readback"},
                                {.pass = "alpha-blend"},
                                {.pass = "decoupled-debug-view"}, {.pass = "exposure"}, {.pass = "bloom"},
                                {.pass = "tonemap"}}});
}

DecoupledRenderer makeDecoupledRenderer(gpu::Device& device, scene::Scene& scene, const plugin::Registry& registry,
                                        plugin::ResolvedFrame frame, std::optional<scene::ShadingMode> mode,
                                        DecoupledSettings settings) {
  DecoupledRenderer r;
  r.shading = std::make_shared<DecoupledShading>(chooseShading(scene, mode), settings);
  r.renderer = std::make_unique<render::Renderer>(device, scene, registry, std::move(frame));
  r.renderer->provideState(kDecoupledState, r.shading);
  return r;
}

DecoupledRenderer makeDecoupledRenderer(gpu::Device& device, scene::Scene& scene, const plugin::Registry& registry,
                                        std::optional<scene::ShadingMode> mode, DecoupledSettings settings,
                                        const std::string& frame) {
  return makeDecoupledRenderer(device, scene, registry, plugin::resolveFrame(registry.frame(frame), registry), mode,
                               settings);
}

}  // namespace sg::plugins
