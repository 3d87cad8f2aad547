// shadelgraph render [scene] -o out.png --size WxH: one frame through the
// render graph, a per-pass timing table, optional stats JSON and Chrome trace.
#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include <shadelgraph/gpu/chrome_trace.hpp>
#include <shadelgraph/image/png.hpp>

#include "animation_player.hpp"
#include "app_session.hpp"
#include "command_options.hpp"
#include "commands.hpp"
#include "frame_setup.hpp"
#include "option_checks.hpp"
#include "output_file.hpp"
#include "scene_source.hpp"
#include "soak_report.hpp"
#include "z_prepass_report.hpp"

namespace sg::app {
namespace {


void printTable(const gpu::FrameTimings& t, uint64_t transientBytes, const gpu::MemoryTotals& memory) {
  std::printf("%-18s %-14s %10s %10s\n", "pass", "queue", "GPU ms", "CPU ms");
  double gpuSum = 0, cpuSum = 0;
  for (const auto& p : t.passes) {
    std::printf("%-18s %-14s %10.3f %10.3f\n", p.name.c_str(), std::string(graph::toString(p.queue)).c_str(), p.gpuMs,
                p.cpuMs);
    gpuSum += p.gpuMs;
    cpuSum += p.cpuMs;
  }
  std::printf("%-18s %-14s %10.3f %10.3f\n", "sum", "", gpuSum, cpuSum);
  std::printf("frame: %.3f ms wall (declare, compile, record, submit, wait), %.3f ms GPU span\n", t.frameMs, t.gpuMs);
  std::printf("memory: %.2f MiB transient heaps", double(transientBytes) / (1 << 20));
  for (const auto& [category, bytes] : memory.bytesByCategory)
    std::printf(", %s %.2f MiB", category.c_str(), double(bytes) / (1 << 20));
  std::printf("\n");
}

void writeStats(const std::string& path, const AppSession& session, const render::FrameResult& frame,
                const std::vector<double>& framesMs, const gpu::MemoryTotals& memory,
                passes::ZPrepassChoice& zPrepass) {
  const auto d = session.decoupled->stats();
  const uint64_t shaded = plugins::shadelsShaded(d.counters);  // the shadel masks' skipped ones not counted
  nlohmann::json passMs = nlohmann::json::object(), passCpuMs = nlohmann::json::object();
  for (const auto& p : frame.timings.passes) {
    passMs[p.name] = p.gpuMs;
    passCpuMs[p.name] = p.cpuMs;
  }
  // Per persistent layer: the fraction of its shadels served from last frame.
  nlohmann::json layerReuse = nlohmann::json::object();
  for (const auto& reuse : d.layerReuse) {
    const uint64_t total = reuse.reused + reuse.computed;
    layerReuse[reuse.layer] = total ? double(reuse.reused) / double(total) : 0.0;
  }
  nlohmann::json memoryJson = nlohmann::json::object();
  for (const auto& [category, bytes] : memory.bytesByCategory) memoryJson[category] = bytes;
  // Each object's shading and why (auto mode's choice, or why it cannot go decoupled).
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& choice : session.decoupled->choices()) {
    const auto report = plugins::shadingReport(choice);  // as inspect prints it
    nlohmann::json object{{"name", session.scene.instances[choice.instance].name},
                          {"shading", report.shading},
                          {"reason", report.reason}};
    // Each primitive is a decoupled object of its own (an alpha-blended one stays forward).
    for (const auto& primitive : report.primitives)
      object["primitives"].push_back({{"shading", primitive.shading}, {"reason", primitive.reason}});
    objects.push_back(std::move(object));
  }
  // Draws the choices took that stay forward all the same (e.g. no room for their triangle-ID map).
  nlohmann::json runTime = nlohmann::json::array();
  for (const auto& f : session.decoupled->runTimeForward())
    runTime.push_back({{"name", session.scene.instances[f.instance].name}, {"primitive", f.primitive}, {"reason", f.reason}});
  // Objects mode auto drew forward in the last frame, and why (tiny, a minified texture without mip levels).
  nlohmann::json thisFrame = nlohmann::json::array();
  for (const auto& f : session.decoupled->frameForward())
    thisFrame.push_back({{"name", session.scene.instances[f.instance].name}, {"primitive", f.primitive}, {"reason", f.reason}});
  nlohmann::json stats{{"frame_ms", frame.timings.frameMs},
                       {"gpu_ms", frame.timings.gpuMs},
                       // GPU time of each raster frame of --frames (first to last timestamp of
                       // what the frame waits for; a shade frame running past it is not included).
                       {"frames_ms", framesMs},
                       {"pass_ms", passMs},
                       {"pass_cpu_ms", passCpuMs},
                       {"triangles", session.renderer->gpuScene().triangleCount()},
                       {"draws", session.renderer->gpuScene().draws().size()},
                       {"transient_bytes", frame.transientBytes},
                       {"plan_reused", frame.planReused},
                       {"memory_bytes", memoryJson},
                       // Decoupled objects are draws (one per primitive): the draws not decoupled this frame.
                       {"objects_forward", session.renderer->gpuScene().draws().size() - d.objects},
                       {"objects_decoupled", d.objects},
                       {"objects", objects},
                       {"forward_at_run_time", runTime},
                       {"forward_this_frame", thisFrame},
                       {"covered_pixels", d.counters.coveredPixels},
                       {"shadels_marked", uint64_t(d.counters.chunksMarked) * 64},
                       {"shadels_allocated", uint64_t(d.counters.chunksAllocated) * 64},
                       {"shadels_shaded", shaded},
                       // Of the shaded chunks, the shadels no pixel reads (shadel masks): not shaded.
                       {"shadels_skipped", d.counters.shadelsSkipped},
                       // Stored (shaded or reused) per covered pixel: at shade rate 1 all are shaded.
                       {"shadels_per_pixel", plugins::shadelsPerCoveredPixel(d.counters)},
                       {"shadels_reused_last_frame", uint64_t(d.counters.chunksReused) * 64},
                       // Over all --frames: raster frames, shade frames among them, shadels the
                       // other frames shaded because nothing valid was stored (the fill), and
                       // shadels copied from the frame before instead of shaded.
                       {"raster_frames", d.rasterFrames},
                       {"shade_frames", d.shadeFrames},
                       {"shadels_filled", d.chunksFilled * 64},
                       {"shadels_reused", d.chunksReused * 64},
                       // The last frame: age in raster frames of the oldest shading composite
                       // read (0: all shaded this frame); budget mode: shadels it left stale
                       // (reused) and those it reshaded for their age, and the age limit.
                       {"shadels_stale_max_age", d.counters.staleMaxAge},
                       {"shadels_left_stale", uint64_t(d.counters.chunksReused) * 64},
                       {"shadels_refreshed", uint64_t(d.counters.chunksRefreshed) * 64},
                       {"stale_age_limit", d.staleAge.limit == plugins::kReuseAnyAge ? nlohmann::json(nullptr)
                                                                                     : nlohmann::json(d.staleAge.limit)},
                       {"overflow_chunks", d.counters.overflowChunks},
                       {"composite_misses", d.counters.compositeMisses},
                       {"global_bias", d.bias},
                       {"shade_storage_bytes", d.storageBytes},
                       {"remap_bytes", d.remapBytes},
                       {"id_map_bytes", d.idMapBytes},
                       {"history_bytes", d.historyBytes},
                       {"support_chunks", d.counters.supportChunks},
                       {"layer_dispatches", d.layerDispatches},
                       {"owned_entries", d.ownedEntries},
                       {"live_entries", d.liveEntries},
                       {"visited_entries", d.visitedEntries},
                       {"visited_entry_groups", d.visitedEntryGroups},
                       {"live_spans", d.liveSpans},
                       {"layers", d.layers},
                       {"layer_reuse", layerReuse},
                       // The forward frame's depth pre-pass: drawn or not, why, and the overdraw measured.
                       {"z_prepass", zPrepassJson(zPrepass)},
                       {"device", session.context->deviceName()}};
  writeTextFile(path, "stats", stats.dump(2) + "\n");
}

constexpr size_t kTracedFrames = 8;

// Every traced frame's passes on one GPU track per logical queue, their
// recording on the CPU track, and a span per frame from its first recorded
// pass until the host had waited for it (a tail, e.g. a shade frame left
// running, goes on on its queue's track). GPU and CPU share one clock where
// the device calibrates its timestamps with the host's.
std::vector<gpu::TraceEvent> traceEvents(const std::vector<gpu::FrameTimings>& frames,
                                         const std::vector<gpu::FrameTimings>& tails) {
  std::vector<gpu::TraceEvent> events;
  if (frames.empty()) return events;
  const double cpuOrigin = frames.front().passes.empty() ? 0.0 : frames.front().passes.front().cpuClockMs;
  const double gpuOrigin = frames.front().clocksAligned  ? cpuOrigin
                           : frames.front().passes.empty() ? 0.0
                                                           : frames.front().passes.front().gpuClockMs;
  const auto add = [&](const gpu::FrameTimings& f, bool tail) {
    if (f.frame < frames.front().frame) return;  // a tail of a frame before the traced ones
    for (const auto& p : f.passes) {
      if (p.tail != tail) continue;  // a tail's times come with the completed tails
      events.push_back({p.name, "GPU " + std::string(graph::toString(p.queue)), p.gpuClockMs - gpuOrigin, p.gpuMs});
    }
  };
  for (const auto& f : frames) {
    add(f, false);
    const std::string frame = "frame " + std::to_string(f.frame);
    for (const auto& p : f.passes)
      events.push_back({frame + " " + p.name, "CPU record", p.cpuClockMs - cpuOrigin, p.cpuMs});
    if (!f.passes.empty())
      events.push_back({frame + " (host waits)", "CPU frames", f.passes.front().cpuClockMs - cpuOrigin,
                        f.doneCpuClockMs - f.passes.front().cpuClockMs});
  }
  for (const auto& t : tails) add(t, true);
  return events;
}

void runRender(const RenderArgs& args) {
  checkRenderArgs(args);
  render::RenderSettings settings = renderSettings(args);
  const plugins::DecoupledSettings decoupled = decoupledSettings(args);
  AppSession session(args.scene, args.mode, decoupled, args.materials, args.frameGraph);
  if (args.camera) checkCameraIndex(session, *args.camera);
  for (const auto& choice : session.decoupled->choices()) {
    if (args.mode != "decoupled") break;
    const char* name = session.scene.instances[choice.instance].name.c_str();
    if (!choice.decoupled) std::printf("forward: %s (%s)\n", name, choice.reason.c_str());
    else
      for (size_t p = 0; p < choice.primitives.size(); ++p)
        if (!choice.primitives[p].eligible)
          std::printf("forward: %s primitive %zu (%s)\n", name, p, choice.primitives[p].reason.c_str());
  }
  if (args.frame) settings.cameraOverride = pathCamera(session, args.path, *args.frame);
  AnimationPlayer animations(session.scene, args.animation);
  // A scene without cameras is framed once, around all its playback: a framing that followed the pose would zoom.
  if (animations.playing() && !settings.cameraOverride && !args.camera && session.scene.cameras.empty())
    settings.cameraOverride = scene::frameBounds(animations.playbackBounds(), float(settings.width) / float(settings.height));
  const auto zPrepass = provideZPrepassChoice(*session.renderer);
  std::optional<SoakReport> soak;
  if (!args.soakReport.empty()) soak.emplace(args.soakReport, uint32_t(args.soakEvery), uint32_t(args.frames));
  // The first frame pays for pipeline creation; report the last one.
  render::FrameResult frame;
  std::vector<double> framesMs;
  // The trace shows the last frames on the executor's clocks (several: frames overlap).
  std::vector<gpu::FrameTimings> traced;
  // The frames end at frame F (--frame, else 0) and at --time: the written image
  // is always that pose of the moving objects and animations, whatever --frames is.
  const int lastFrame = args.frame.value_or(0);
  for (int i = 0; i < args.frames; ++i) {
    const int before = args.still ? 0 : args.frames - 1 - i;  // frames before the last
    settings.time = float(lastFrame - before) / 30.0f;
    if (animations.playing()) animations.poseAt(float(args.time - before / args.fps), *session.renderer);
    settings.readback = i + 1 == args.frames;  // only the last is written (and a readback waits for the queue)
    frame = session.renderer->render(settings);
    session.decoupled->observeTimings(frame.timings);
    if (soak) soak->add(uint32_t(i), frame.timings);
    framesMs.push_back(frame.timings.gpuMs);
    if (!args.trace.empty()) {
      traced.push_back(frame.timings);
      if (traced.size() > kTracedFrames) traced.erase(traced.begin());
    }
  }
  if (args.mode == "decoupled")
    for (const auto& f : session.decoupled->runTimeForward())
      std::printf("forward: %s primitive %u (%s)\n", session.scene.instances[f.instance].name.c_str(), f.primitive,
                  f.reason.c_str());
  for (const auto& f : session.decoupled->frameForward())
    std::printf("forward this frame: %s primitive %u (%s)\n", session.scene.instances[f.instance].name.c_str(), f.primitive,
                f.reason.c_str());
  for (const auto& shrunk : session.decoupled->shrunkIdMaps())
    std::printf("warning: object '%s' primitive %u: triangle-ID map shrunk to fit the %.0f MiB buffer, level 0 %u -> %u\n",
                session.scene.instances[shrunk.instance].name.c_str(), shrunk.primitive,
                double(shrunk.bufferBytes) / (1 << 20), shrunk.wantedLevel0, shrunk.level0);
  image::writePng(args.output, frame.image.width, frame.image.height, frame.image.rgba8.data());
  const auto memory = session.device->memory().totals();
  printTable(frame.timings, frame.transientBytes, memory);
  printZPrepass(*zPrepass);
  const auto d = session.decoupled->stats();
  std::printf("wrote %s (%ux%u, %zu triangles, %zu draws, %u objects decoupled, %zu forward)\n", args.output.c_str(),
              frame.image.width, frame.image.height, session.renderer->gpuScene().triangleCount(),
              session.renderer->gpuScene().draws().size(), d.objects, session.renderer->gpuScene().draws().size() - d.objects);
  if (d.objects)
    std::printf("decoupled: bias %.2f, %u chunks marked, %u allocated of %u, %u overflowed, %u composite misses, "
                "%.2f shadels per covered pixel\n",
                double(d.bias), d.counters.chunksMarked, d.counters.chunksAllocated, d.capacityChunks,
                d.counters.overflowChunks, d.counters.compositeMisses,
                plugins::shadelsPerCoveredPixel(d.counters));
  if (d.objects && args.shadeBudget)
    std::printf("shade budget %.2f ms (%.4f ms a chunk): last frame %u chunks shaded (%u for their age), %u left "
                "stale, oldest %u frames\n",
                *args.shadeBudget, d.msPerChunk, d.counters.chunksShaded, d.counters.chunksRefreshed,
                d.counters.chunksReused, d.counters.staleMaxAge);
  if (d.objects && args.shadeRate > 1)
    std::printf("shade rate %d: %llu shade frames of %llu; last frame %s, %u chunks shaded, %u reused; over the run "
                "%llu chunks filled, %llu reused\n",
                args.shadeRate, (unsigned long long)d.shadeFrames, (unsigned long long)d.rasterFrames,
                d.shadeFrame ? "a shade frame" : "a fill frame", d.counters.chunksShaded, d.counters.chunksReused,
                (unsigned long long)d.chunksFilled, (unsigned long long)d.chunksReused);
  if (soak) soak->finish();
  if (!args.stats.empty()) writeStats(args.stats, session, frame, framesMs, memory, *zPrepass);
  if (!args.trace.empty()) {
    const auto tails = session.renderer->finishFrames();
    gpu::writeChromeTrace(args.trace, traceEvents(traced, tails));
  }
  setExitCode(session.validationExitCode());
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  static RenderArgs args;
  auto* cmd = app.add_subcommand("render", "Render one frame of a scene to a PNG");
  addRenderOptions(*cmd, args);
  cmd->callback([] { runRender(args); });
}

}  // namespace sg::app
