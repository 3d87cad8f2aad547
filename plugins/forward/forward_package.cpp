#include "forward_package.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <shadelgraph/render/environment_binding.hpp>
#include <shadelgraph/render/frame_context.hpp>
#include <shadelgraph/render/frame_uniforms.hpp>
#include <shadelgraph/render/light_binding.hpp>
#include <shadelgraph/render/shadow_binding.hpp>
#include <shadelgraph/render/shadow_views.hpp>

#include "alpha-blend/alpha_blend.hpp"
#include "alpha-mask/alpha_mask.hpp"
#include "bloom/bloom.hpp"
#include "environment/environment.hpp"
#include "exposure/exposure.hpp"
#include "forward/forward.hpp"
#include "forward/forward_material.hpp"
#include "light-cull/light_cull.hpp"
#include "object-pick/object_pick.hpp"
#include "shadows/shadows.hpp"
#include "skinning/skinning.hpp"
#include "occlusion-cull/occlusion_cull.hpp"
#include "tonemap/tonemap.hpp"
#include "z-prepass/z_prepass.hpp"
#include "z-prepass/z_prepass_choice.hpp"

namespace sg::plugins {
namespace {

using render::FrameContext;

// Above this many lights with a range a frame culls them per cluster (measured:
// docs/many-lights.md); 8 was the old cap, so no frame that rendered before gains the pass.
constexpr uint32_t kLightCullThreshold = 8;

graph::ResourceHandle depthTarget(FrameContext& ctx) {
  return ctx.has("scene.depth") ? ctx.read("scene.depth")
                                : ctx.graph().createImage("depth", {.format = graph::Format::D32F});
}

// Decoupled alpha-mask draws of the frame: the z-prepass gives them depth
// where their alpha test keeps them (shadel-mark and composite test against it).
std::vector<uint32_t> alphaTestedDraws(FrameContext& ctx) {
  std::vector<uint32_t> tested;
  const auto& draws = ctx.gpuScene().draws();
  for (const uint32_t d : ctx.draws().decoupled)
    if (draws[d].alphaMode == scene::AlphaMode::Mask) tested.push_back(d);
  return tested;
}

glm::vec3 background(FrameContext& ctx) { return passes::hdrBackground(ctx.inputs().scene.lights); }

// Occlusion culling in two halves around the first pass that draws depth:
// the frame's draw commands start as the persistent ones (last frame's
// visibility), so that pass draws the draws visible last frame.
bool occlusionCulled(FrameContext& ctx) {
  return ctx.inputs().culling && ctx.visibleDraws().size() > 1;  // one draw has nothing to hide behind
}

void importDrawCommands(FrameContext& ctx, render::DrawCulling& culling) {
  // Where the draw commands rest between frames: read as indirect arguments and written by the cull.
  const graph::ResourceState resting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                     graph::AccessFlag::IndirectCommandRead | graph::AccessFlag::ShaderStorageRead |
                                         graph::AccessFlag::ShaderStorageWrite};
  render::DrawCommands& commands = ctx.drawCommands();
  commands.handle = ctx.graph().importPersistentBuffer("draw commands", {.size = culling.commandBytes()}, resting);
  commands.buffer = culling.commands().handle();
  ctx.inputs().executor.bindBuffer(commands.handle, culling.commands());
}

// The second half: every draw tested against `depth` (hi-z, occlusion-cull);
// the passes after it draw only the visible ones. Returns the late commands
// (draws found visible that the first half did not draw).
graph::ResourceHandle occlusionCull(FrameContext& ctx, graph::ResourceHandle depth) {
  const auto& in = ctx.inputs();
  render::DrawCommands& commands = ctx.drawCommands();
  const auto cull = passes::addOcclusionCull(ctx.graph(), *in.culling, in.viewProjection, in.width, in.height, depth,
                                             commands.handle);
  commands.handle = cull.commands;
  return cull.late;
}

// Draws a package adds to the depth pre-pass (render::DepthPassDraws), if any.
render::DepthPassDraws* packageDraws(FrameContext& ctx) {
  auto& draws = ctx.depthPassDraws();
  return draws ? &*draws : nullptr;
}

// The depth pre-pass, occlusion-culled: the draws visible last frame first,
// then every draw tested against that depth, then the draws found visible
// that were not drawn yet.
graph::ResourceHandle culledZPrepass(FrameContext& ctx, passes::OverdrawProbe* probe) {
  importDrawCommands(ctx, *ctx.inputs().culling);
  const auto view = ctx.view(ctx.visibleDraws());
  const auto tested = alphaTestedDraws(ctx);
  const auto depth = passes::addZPrepass(ctx.graph(), view, depthTarget(ctx), tested,
                                         {probe, passes::OverdrawSlot::Prepass}, packageDraws(ctx));
  return passes::addZPrepassLate(ctx.graph(), view, depth, occlusionCull(ctx, depth), tested,
                                 {probe, passes::OverdrawSlot::PrepassLate}, packageDraws(ctx));
}

passes::ZPrepassChoice& zPrepassChoice(FrameContext& ctx) {
  return ctx.ownState<passes::ZPrepassChoice>(passes::kZPrepassChoiceState);
}

// What the z-prepass choice weighs: the visible opaque forward draws'
// triangles, and the textures their materials sample per triangle.
passes::OverdrawView overdrawView(FrameContext& ctx) {
  const auto& in = ctx.inputs();
  passes::OverdrawView view{in.width, in.height, 0, 0.0, in.viewProjection};
  double textures = 0.0;
  for (const uint32_t d : ctx.draws().forward) {
    const auto& draw = ctx.gpuScene().draws()[d];
    if (draw.alphaMode != scene::AlphaMode::Opaque) continue;
    view.triangles += draw.indexCount / 3;
    if (draw.material >= in.scene.materials.size()) continue;
    const auto slots = in.scene.materials[draw.material].textureSlots();
    textures += double(draw.indexCount / 3) *
                double(std::count_if(slots.begin(), slots.end(), [](const scene::TextureRef& t) { return t.present(); }));
  }
  if (view.triangles) view.texturesPerTriangle = textures / double(view.triangles);
  return view;
}

// Does this frame draw the depth pre-pass? Always with decoupled objects
// visible (shadel-mark and composite test its depth), after an earlier pass
// drew depth, or when a pass before forward-opaque reads the depth (e.g. the
// ssao plugin) other than one drawing only decoupled objects (it reads
// view.decoupled; there are none). Otherwise as the setting says, Auto by
// the overdraw measured (passes::ZPrepassChoice, which may make this frame a
// measurement frame); without it forward-opaque writes the depth.
bool drawsZPrepass(FrameContext& ctx) {
  passes::ZPrepassChoice& choice = zPrepassChoice(ctx);
  const auto forced = [&](bool drawn, const char* reason) {
    choice.recordForced(drawn, reason);
    return drawn;
  };
  if (!ctx.draws().decoupled.empty()) return forced(true, "decoupled objects visible (shadel-mark and composite use its depth)");
  if (ctx.has("scene.depth")) return forced(true, "an earlier pass drew depth");
  const auto reads = [](const plugin::PassPlugin& p, const char* resource) {
    return std::find(p.reads.begin(), p.reads.end(), resource) != p.reads.end();
  };
  for (const auto& later : ctx.passesBetween("forward-opaque"))
    if (reads(*later.pass, "scene.depth") && !reads(*later.pass, plugin::kDecoupledDrawsResource))
      return forced(true, "a pass before forward-opaque reads the depth");
  switch (ctx.inputs().zPrepass) {
    case render::ZPrepass::On: return forced(true, "forced on");
    case render::ZPrepass::Off: return forced(false, "forced off");
    case render::ZPrepass::Auto: break;
  }
  return choice.decide(ctx.inputs().device.context(), overdrawView(ctx), ctx.inputs().frameNumber).prepass;
}

// forward-opaque where no pre-pass drew the depth (it writes the depth
// itself), occlusion-culled in the same two halves as the pre-pass.
passes::ForwardTargets culledForwardOpaque(FrameContext& ctx, const render::SceneView& view,
                                           passes::ForwardTargets t) {
  importDrawCommands(ctx, *ctx.inputs().culling);
  t = passes::addForwardOpaque(ctx.graph(), view, t, background(ctx));
  return passes::addForwardOpaqueLate(ctx.graph(), view, t, occlusionCull(ctx, t.depth));
}

passes::ForwardTargets targets(FrameContext& ctx) { return {ctx.read("scene.hdr"), ctx.read("scene.depth")}; }

void publish(FrameContext& ctx, const passes::ForwardTargets& t) {
  ctx.write("scene.hdr", t.color);
  ctx.write("scene.depth", t.depth);
}

// Whether draw `d` is a caster in shadow map `v`: inside the map's view, reached by its light, not alpha-blended.
bool castsInto(const FrameContext& ctx, const render::ShadowView& v, uint32_t d) {
  const auto& in = ctx.inputs();
  return ctx.gpuScene().draws()[d].alphaMode != scene::AlphaMode::Blend &&
         render::castsInto(v, in.scene.lights[v.light], in.drawSpheres[d]);
}

// The frame's shadow maps (render::shadowViews: shadowed lights that reach a
// visible draw), each holding the draws inside its view that its light reaches
// (casters may be off screen); none: no pass, no atlas.
void declareShadows(FrameContext& ctx) {
  const auto& in = ctx.inputs();
  if (in.shadowViews.empty()) return;
  const auto& draws = ctx.gpuScene().draws();
  std::vector<passes::ShadowMapDraws> maps;
  for (const render::ShadowView& v : in.shadowViews) {
    passes::ShadowMapDraws map{v.slot, {}};
    for (uint32_t d = 0; d < draws.size(); ++d)
      if (castsInto(ctx, v, d)) map.casters.push_back(d);
    maps.push_back(std::move(map));
  }
  ctx.write(render::kShadowMapsResource, passes::addShadowMaps(ctx.graph(), ctx.view(ctx.gpuScene().allDraws()),
                                                               std::move(maps), uint32_t(in.shadowViews.size())));
}

// Deforms the skinned and morphed objects when one of them is visible or
// casts into one of the frame's shadow maps (all of them then: one pass).
void declareSkinning(FrameContext& ctx) {
  const render::DeformationFrame* deformation = ctx.inputs().deformation;
  if (!deformation) return;
  const auto visible = ctx.visibleDraws();
  const auto& draws = ctx.gpuScene().draws();
  const auto deformed = [&](uint32_t d) { return deformation->deformation.deformed(draws[d].instance); };
  const auto casts = [&](uint32_t d) {
    return std::any_of(ctx.inputs().shadowViews.begin(), ctx.inputs().shadowViews.end(),
                       [&](const render::ShadowView& v) { return castsInto(ctx, v, d); });
  };
  bool needed = std::any_of(visible.begin(), visible.end(), deformed);
  for (uint32_t d = 0; !needed && d < draws.size(); ++d) needed = deformed(d) && casts(d);
  if (!needed) return;
  ctx.write(render::kSceneVerticesResource,
            passes::addSkinning(ctx.graph(), ctx.inputs().executor, ctx.gpuScene(), *deformation));
}

// The light grid, when the frame has more lights with a range (the only ones
// a cluster can leave out) than the pass's threshold and something visible to
// shade; otherwise no pass and no grid (every light loop visits every light).
void declareLightCull(FrameContext& ctx) {
  const auto& in = ctx.inputs();
  const auto lights = uint32_t(std::max<size_t>(in.scene.lights.size(), 1));  // a scene without lights gets a sun
  const auto ranged = uint32_t(std::count_if(in.scene.lights.begin(), in.scene.lights.end(), [](const scene::Light& l) {
    return l.type != scene::LightType::Directional && l.range > 0.0f;
  }));
  const int threshold = ctx.parameter<int>("threshold");
  if (threshold < 0) throw plugin::FrameError("pass 'light-cull': parameter 'threshold' must be 0 or more");
  const auto visible = ctx.visibleDraws();
  if (ranged <= uint32_t(threshold) || visible.empty()) return;
  std::vector<glm::vec4> spheres;
  for (const uint32_t d : visible) spheres.push_back(in.drawSpheres[d]);
  const auto grid = passes::lightGridFor(in.width, in.height, in.viewProjection, spheres, lights);
  ctx.write(render::kLightGridResource, passes::addLightCull(ctx.graph(), ctx.view({}), grid, lights));
}

}  // namespace

void registerForwardPackage(plugin::Registry& registry) {
  registry.addPass({.name = "skinning",
                    .description = "skinned and morphed objects' vertices for this frame (compute; only when one is visible)",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {render::kSceneVerticesResource},
                    .declare = declareSkinning});
  registry.addPass({.name = "z-prepass",
                    .description = "depth of every visible opaque object, forward or decoupled, and of decoupled alpha-mask objects (alpha-tested), "
                                   "with the draws a package adds (decoupled, bilinear: shadel-mark's requests); "
                                   "without decoupled objects only where overdraw pays for it (else forward-opaque writes the depth)",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {"scene.depth"},
                    .declare = [](FrameContext& ctx) {
                      if (!drawsZPrepass(ctx)) {
                        ctx.write("scene.depth", depthTarget(ctx));  // unwritten: forward-opaque draws it
                        return;
                      }
                      passes::OverdrawProbe* probe = zPrepassChoice(ctx).probeFor(ctx.inputs().frameNumber);
                      if (occlusionCulled(ctx)) {
                        ctx.write("scene.depth", culledZPrepass(ctx, probe));
                        return;
                      }
                      ctx.write("scene.depth",
                                passes::addZPrepass(ctx.graph(), ctx.view(ctx.visibleDraws()), depthTarget(ctx),
                                                    alphaTestedDraws(ctx), {probe, passes::OverdrawSlot::Prepass},
                                                    packageDraws(ctx)));
                    }});
  registry.addPass({.name = "object-pick",
                    .description = "the object under a pixel, read back (only in a frame with a pick pending: "
                                   "the viewer's click)",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {plugin::kPickResource},
                    .declare = [](FrameContext& ctx) {
                      if (!ctx.has(plugin::kPickResource)) return;
                      const auto& in = ctx.inputs();
                      ctx.write(plugin::kPickResource,
                                passes::addObjectPick(ctx.graph(), ctx.view(ctx.visibleDraws()), *in.pick,
                                                      {in.width, in.height}, ctx.read(plugin::kPickResource)));
                    }});
  registry.addPass({.name = "shadows",
                    .description = "shadow maps (spot: one, point: six cube faces, directional: cascades) of the shadowed lights that reach a visible object (only then)",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {render::kShadowMapsResource},
                    .declare = declareShadows});
  registry.addPass({.name = "environment",
                    .description = "the scene's environment image prefiltered once for image-based lighting "
                                   "(only when the scene names one; the prefilter passes only until they ran)",
                    .writes = {render::kEnvironmentIrradianceResource, render::kEnvironmentSpecularResource,
                               render::kEnvironmentBrdfResource, passes::kEnvironmentImageResource},
                    .declare = passes::addEnvironment});
  registry.addPass({.name = "environment-background",
                    .description = "the environment image behind everything, where nothing was drawn "
                                   "(only when the scene names one; before alpha-blend, which blends over it)",
                    .reads = {passes::kEnvironmentImageResource, "scene.hdr", "scene.depth"},
                    .writes = {"scene.hdr"},
                    .declare = [](FrameContext& ctx) {
                      if (!ctx.inputs().scene.environment.present()) return;
                      ctx.write("scene.hdr", passes::addEnvironmentBackground(ctx, ctx.read("scene.hdr"),
                                                                              ctx.read("scene.depth")));
                    }});
  registry.addPass({.name = "light-cull",
                    .description = "clustered light culling: which lights reach each screen tile and depth slice "
                                   "(only when the frame has more lights with a range than the threshold)",
                    .reads = {plugin::kForwardDrawsResource},
                    .writes = {render::kLightGridResource},
                    .parameters = {{"threshold", int(kLightCullThreshold),
                                    "point and spot lights with a range a frame may have without culling (docs/many-lights.md)"}},
                    .declare = declareLightCull});
  registry.addPass({.name = "forward-opaque",
                    .description = "opaque objects shaded forward (their material's fragment variant); clears the HDR "
                                   "colour (with none, in a frame with decoupled objects, no pass: the first pass "
                                   "drawing into the colour clears it)",
                    .reads = {plugin::kForwardDrawsResource, "scene.depth"},
                    .writes = {"scene.hdr", "scene.depth"},
                    .declare = [](FrameContext& ctx) {
                      const passes::ForwardTargets t{ctx.graph().createImage("hdr", {.format = graph::Format::RGBA16F}),
                                                     ctx.read("scene.depth")};
                      const auto view = ctx.view(ctx.draws().forward);
                      // A pass that only clears would keep the colour alive from here, during
                      // the decoupled objects' shading on async compute, so it could share
                      // memory with none of their transients: composite clears it instead
                      // (a frame without composite: this pass clears).
                      if (!passes::hasAlphaMode(view, scene::AlphaMode::Opaque) && !ctx.draws().decoupled.empty() &&
                          ctx.runsLater("composite")) {
                        publish(ctx, t);  // unwritten: see passes::clearIfUnwritten
                        return;
                      }
                      if (t.depth.version == 0 && occlusionCulled(ctx)) {  // the z-prepass left the depth to this pass
                        publish(ctx, culledForwardOpaque(ctx, view, t));
                        return;
                      }
                      // In a z-prepass measurement frame it counts the fragments it shades.
                      publish(ctx, passes::addForwardOpaque(ctx.graph(), view, t, background(ctx),
                                                            {zPrepassChoice(ctx).probeFor(ctx.inputs().frameNumber),
                                                             passes::OverdrawSlot::ForwardOpaque}));
                    }});
  registry.addPass({.name = "alpha-mask",
                    .description = "alpha-tested objects (only when a visible object has such a material)",
                    .reads = {plugin::kForwardDrawsResource, "scene.hdr", "scene.depth"},
                    .writes = {"scene.hdr", "scene.depth"},
                    .declare = [](FrameContext& ctx) {
                      const auto view = ctx.view(ctx.draws().forward);
                      if (passes::hasAlphaMode(view, scene::AlphaMode::Mask))
                        publish(ctx, passes::addAlphaMask(ctx.graph(), view, targets(ctx),
                                                          passes::clearIfUnwritten(ctx.read("scene.hdr"), background(ctx))));
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
                    .description = "exposure as EV100: manual, or automatic from the log-average luminance, adapted "
                                   "across frames (async compute)",
                    .queue = graph::QueueClass::AsyncCompute,
                    .reads = {"scene.hdr"},
                    .writes = {"scene.exposure"},
                    .parameters = {{"mode", "auto", "\"auto\" (metered) or \"manual\" (ev100)"},
                                   {"ev100", 0.0, "manual: the exposure value at ISO 100 (sunny day ~15, indoors ~7)"},
                                   {"compensation", 0.0, "auto: EV added to the brightness (+1 twice as bright)"},
                                   {"adaptation", 1.0, "auto: fraction of the gap to the metering closed per frame "
                                                       "(1: each frame metered alone)"},
                                   {"min-ev100", -3.585, "auto: lowest EV100 (the default caps the gain at 10)"},
                                   {"max-ev100", 24.0, "auto: highest EV100 (a 100,000-lux sun meters about 16)"}},
                    .declare = [](FrameContext& ctx) {
                      ctx.write("scene.exposure",
                                passes::addExposure(ctx, ctx.read("scene.hdr"), passes::exposureParams(ctx)));
                    }});
  registry.addPass({.name = "bloom",
                    .description = "light above white spread by a down/upsample pyramid (only when a visible object "
                                   "emits at least 'threshold')",
                    .reads = {plugin::kForwardDrawsResource, "scene.hdr", "scene.exposure"},
                    .writes = {"scene.hdr"},
                    .parameters = {{"threshold", double(passes::kBloomThreshold),
                                    "emission (cd/m^2) of a visible object that calls for bloom"},
                                   {"strength", 0.5, "how much of the light above white the halo carries"},
                                   {"levels", double(passes::kBloomLevels), "halvings of the pyramid, 1 to 8"}},
                    .declare = [](FrameContext& ctx) {
                      const float threshold = ctx.parameter<float>("threshold");
                      const float strength = ctx.parameter<float>("strength");
                      const float levels = ctx.parameter<float>("levels");
                      if (!(threshold >= 0.0f) || !(strength >= 0.0f && strength <= 100.0f) ||
                          !(levels >= 1.0f && levels <= 8.0f) || levels != std::floor(levels))
                        throw std::runtime_error("pass 'bloom': parameters 'threshold' >= 0, 'strength' 0 to 100, "
                                                 "'levels' a whole number 1 to 8");
                      if (!passes::bloomCalledFor(ctx.inputs().scene, ctx.gpuScene(), ctx.visibleDraws(), threshold))
                        return;
                      ctx.write("scene.hdr", passes::addBloom(ctx.graph(), ctx.read("scene.hdr"),
                                                              ctx.read("scene.exposure"), strength, uint32_t(levels)));
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
                     .passes = {{.pass = "skinning"}, {.pass = "z-prepass"}, {.pass = "object-pick"}, {.pass = "shadows"}, {.pass = "environment"}, {.pass = "light-cull"},
                                {.pass = "forward-opaque"}, {.pass = "alpha-mask"}, {.pass = "environment-background"},
                                {.pass = "alpha-blend"}, {.pass = "exposure"}, {.pass = "bloom"}, {.pass = "tonemap"}}});
}

}  // namespace sg::plugins
