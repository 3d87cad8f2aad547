#include "bench_effects.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include <builtin_plugins.hpp>
#include <decoupled/decoupled_package.hpp>
#include <procedural_sky.hpp>
#include <shadelgraph/image/flip.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "bench_effect_scenes.hpp"
#include "bench_materials.hpp"
#include "output_file.hpp"

namespace sg::app {
namespace {

// Manual exposure per scene (EV100), chosen so each set's mid-tones sit mid-grey.
constexpr double kShadowsEv = 1.5, kLightsEv = 1.0, kIblEv = 2.5, kBloomEv = 2.5;

// One configuration of a comparison: a scene, a path and pass parameters over the decoupled frame's.
struct Variant {
  std::string name;
  bool decoupled = false;
  scene::Scene scene;
  nlohmann::json parameters = nlohmann::json::object();  // {"pass": {"parameter": value}}
};

struct Measured {
  std::vector<double> gpuMs;
  std::map<std::string, std::vector<double>> passMs;
  image::Rgba8Image image;  // the last timed frame
  double gpuMsMedian() const { return median(gpuMs); }
  double passMedian(const std::string& prefix) const {
    // Passes sharing a prefix ("layer-shade", "layer-shade #2") summed per frame, then the median.
    std::vector<double> sums(gpuMs.size(), 0.0);
    bool any = false;
    for (const auto& [name, values] : passMs)
      if (name.rfind(prefix, 0) == 0)
        for (size_t i = 0; i < values.size() && i < sums.size(); ++i) sums[i] += values[i], any = true;
    return any ? median(sums) : 0.0;
  }
};

struct Session {
  scene::Scene scene;
  std::shared_ptr<plugins::DecoupledShading> shading;
  std::unique_ptr<render::Renderer> renderer;
};

std::unique_ptr<Session> makeSession(gpu::Device& device, const Variant& v) {
  auto session = std::make_unique<Session>();
  session->scene = v.scene;
  const auto& registry = plugins::builtinRegistry();
  plugin::FrameDescription frame{.name = "bench " + v.name, .base = "decoupled"};
  for (const auto& [pass, values] : v.parameters.items()) frame.parameters[pass] = values;
  auto made = plugins::makeDecoupledRenderer(device, session->scene, registry, plugin::resolveFrame(frame, registry),
                                             v.decoupled ? scene::ShadingMode::Decoupled : scene::ShadingMode::Forward,
                                             plugins::DecoupledSettings{.filter = 1});
  session->shading = std::move(made.shading);
  session->renderer = std::move(made.renderer);
  return session;
}

void addSamples(Measured& m, const render::FrameResult& frame) {
  m.gpuMs.push_back(frame.timings.gpuMs);
  for (const auto& p : frame.timings.passes) m.passMs[p.name].push_back(p.gpuMs);
}

// Renders every variant once a round, in order, one warm-up round then
// `repetitions` timed ones; `eachRound` (when set) runs inside every timed
// round after the variants, so what it measures alternates with them too.
std::vector<Measured> alternate(gpu::Device& device, const std::vector<Variant>& variants, uint32_t width,
                                uint32_t height, int repetitions, const std::string& label,
                                const std::function<void()>& eachRound = {}) {
  std::vector<std::unique_ptr<Session>> sessions;
  for (const auto& v : variants) sessions.push_back(makeSession(device, v));
  // One camera for all: the variants of a comparison differ in lights or effects, not in view.
  const scene::Camera camera = sessions.front()->renderer->camera({.width = width, .height = height});
  std::fprintf(stderr, "[bench] effects %ux%u: %s, %zu configurations, %d rounds\n", width, height, label.c_str(),
               variants.size(), repetitions);
  std::vector<Measured> measured(variants.size());
  for (int rep = -1; rep < repetitions; ++rep) {
    for (size_t i = 0; i < sessions.size(); ++i) {
      auto frame = sessions[i]->renderer->render({.width = width, .height = height, .cameraOverride = camera});
      if (rep < 0) continue;  // warm-up: pipelines, the adjuster, one-time passes (the environment prefilter)
      addSamples(measured[i], frame);
      if (rep == repetitions - 1) measured[i].image = toImage(frame.image);
    }
    if (rep >= 0 && eachRound) eachRound();
  }
  return measured;
}

double flipMean(const image::Rgba8Image& reference, const image::Rgba8Image& test) {
  return image::flipLdr(reference, test).mean;
}

nlohmann::json exposure(double ev100) { return {{"mode", "manual"}, {"ev100", ev100}}; }

std::string pathName(bool decoupled) { return decoupled ? "decoupled" : "forward"; }

void savePng(const std::filesystem::path& out, const std::string& name, const image::Rgba8Image& img) {
  image::writePng(out / ("effects-" + name + ".png"), img.width, img.height, img.pixels.data());
}

// Shadows: per light type, the same lights with 0, 1, 2, ... of them shadowed, both paths.
nlohmann::json benchShadows(gpu::Device& device, uint32_t width, uint32_t height, int repetitions,
                            const std::filesystem::path& out, const std::string& tag) {
  nlohmann::json results = nlohmann::json::array();
  for (const auto type : {scene::LightType::Directional, scene::LightType::Spot, scene::LightType::Point}) {
    // The 16-map atlas: 4 suns x 4 cascades, 4 spots, 2 point lights x 6 faces.
    const uint32_t lights = type == scene::LightType::Point ? 2 : 4;
    std::vector<uint32_t> counts{0, 1, 2};
    if (lights == 4) counts.push_back(4);
    std::vector<Variant> variants;
    for (const bool decoupled : {false, true})
      for (const uint32_t k : counts)
        variants.push_back({pathName(decoupled) + " " + std::to_string(k) + " shadowed", decoupled,
                            shadowBenchScene(type, lights, k), {{"exposure", exposure(kShadowsEv)}}});
    const auto measured = alternate(device, variants, width, height, repetitions, lightTypeName(type) + " shadows");
    for (const bool decoupled : {false, true}) {
      const size_t base = decoupled ? counts.size() : 0;
      const Measured& none = measured[base];
      const Measured& all = measured[base + counts.size() - 1];
      nlohmann::json rows = nlohmann::json::array();
      for (size_t c = 0; c < counts.size(); ++c) {
        const Measured& m = measured[base + c];
        const double extra = m.gpuMsMedian() - none.gpuMsMedian();
        rows.push_back({{"shadowed", counts[c]},
                        {"frame_ms_median", m.gpuMsMedian()},
                        {"frame_ms_samples", m.gpuMs},
                        {"shadows_pass_ms_median", m.passMedian("shadows")},
                        {"shading_ms_median", m.passMedian(decoupled ? "layer-shade" : "forward-opaque")},
                        {"ratio_to_unshadowed", m.gpuMsMedian() / none.gpuMsMedian()},
                        {"ms_per_shadowed_light", counts[c] ? nlohmann::json(extra / counts[c]) : nlohmann::json(nullptr)},
                        {"flip_against_all_shadowed", flipMean(all.image, m.image)}});
      }
      const std::string name = tag + "-shadows-" + lightTypeName(type) + "-" + pathName(decoupled);
      savePng(out, name + "-none", none.image);
      savePng(out, name + "-all", all.image);
      results.push_back({{"light_type", lightTypeName(type)},
                         {"path", pathName(decoupled)},
                         {"lights", lights},
                         {"flip_unshadowed_against_shadowed", flipMean(all.image, none.image)},
                         {"rows", rows}});
    }
  }
  return results;
}

// Many lights: culled (threshold 0) against brute force at each count, both paths.
nlohmann::json benchLights(gpu::Device& device, uint32_t width, uint32_t height, int repetitions,
                           const std::vector<int>& counts, const std::filesystem::path& out, const std::string& tag) {
  nlohmann::json rows = nlohmann::json::array();
  for (const int count : counts) {
    const scene::Scene scene = manyLightsBenchScene(uint32_t(count));
    const nlohmann::json culled{{"light-cull", {{"threshold", 0}}}, {"exposure", exposure(kLightsEv)}};
    const nlohmann::json brute{{"light-cull", {{"threshold", count}}}, {"exposure", exposure(kLightsEv)}};
    std::vector<Variant> variants;
    for (const bool decoupled : {false, true}) {
      variants.push_back({pathName(decoupled) + " culled", decoupled, scene, culled});
      variants.push_back({pathName(decoupled) + " brute force", decoupled, scene, brute});
    }
    const auto measured =
        alternate(device, variants, width, height, repetitions, std::to_string(count) + " point lights");
    for (const bool decoupled : {false, true}) {
      const Measured& c = measured[decoupled ? 2 : 0];
      const Measured& b = measured[decoupled ? 3 : 1];
      const char* shading = decoupled ? "layer-shade" : "forward-opaque";
      rows.push_back({{"lights", count},
                      {"range", scene.lights.front().range},
                      {"path", pathName(decoupled)},
                      {"culled_ms_median", c.gpuMsMedian()},
                      {"brute_force_ms_median", b.gpuMsMedian()},
                      {"culled_ms_samples", c.gpuMs},
                      {"brute_force_ms_samples", b.gpuMs},
                      {"brute_force_over_culled", b.gpuMsMedian() / c.gpuMsMedian()},
                      {"light_cull_pass_ms_median", c.passMedian("light-cull")},
                      {"culled_shading_ms_median", c.passMedian(shading)},
                      {"brute_force_shading_ms_median", b.passMedian(shading)},
                      {"flip_culled_against_brute_force", flipMean(b.image, c.image)}});
      if (count == counts.back())
        savePng(out, tag + "-lights-" + std::to_string(count) + "-" + pathName(decoupled), c.image);
    }
  }
  // The crossover per path: the smallest count from which culling is faster at every larger count measured.
  nlohmann::json crossover = nlohmann::json::object();
  for (const bool decoupled : {false, true}) {
    std::optional<int> from;
    for (const auto& r : rows) {
      if (r["path"] != pathName(decoupled)) continue;
      if (r["brute_force_over_culled"].get<double>() > 1.0) {
        if (!from) from = r["lights"].get<int>();
      } else {
        from.reset();
      }
    }
    crossover[pathName(decoupled)] = from ? nlohmann::json(*from) : nlohmann::json(nullptr);
  }
  return {{"lights_in_reach", kLightsInReach}, {"rows", rows}, {"culling_faster_from", crossover}};
}

// Environment light against the analytic sky; the prefilter from the first frame of a fresh renderer each round.
nlohmann::json benchIbl(gpu::Device& device, uint32_t width, uint32_t height, int repetitions,
                        const std::filesystem::path& out, const std::string& tag) {
  const auto skyFile = out / "effects-sky.hdr";
  bench::writeProceduralSky(skyFile);
  const scene::Scene sky = iblBenchScene(), lit = iblBenchScene(skyFile);
  const nlohmann::json parameters{{"exposure", exposure(kIblEv)}};
  std::vector<Variant> variants;
  for (const bool decoupled : {false, true}) {
    variants.push_back({pathName(decoupled) + " analytic sky", decoupled, sky, parameters});
    variants.push_back({pathName(decoupled) + " environment", decoupled, lit, parameters});
  }
  // The one-time cost: a fresh forward renderer's first frame, prefilter passes apart.
  Measured firstFrames;
  std::vector<double> prefilterMs;
  const Variant fresh{"forward environment (first frame)", false, lit, parameters};
  const auto measureFirstFrame = [&] {
    auto session = makeSession(device, fresh);
    const auto frame = session->renderer->render(
        {.width = width, .height = height, .cameraOverride = session->renderer->camera({.width = width, .height = height})});
    addSamples(firstFrames, frame);
    double ms = 0.0;
    for (const auto& p : frame.timings.passes)
      if (p.name.rfind("environment-", 0) == 0) ms += p.gpuMs;
    prefilterMs.push_back(ms);
  };
  const auto measured = alternate(device, variants, width, height, repetitions, "environment light", measureFirstFrame);
  nlohmann::json rows = nlohmann::json::array();
  for (const bool decoupled : {false, true}) {
    const Measured& s = measured[decoupled ? 2 : 0];
    const Measured& e = measured[decoupled ? 3 : 1];
    rows.push_back({{"path", pathName(decoupled)},
                    {"analytic_sky_ms_median", s.gpuMsMedian()},
                    {"environment_ms_median", e.gpuMsMedian()},
                    {"analytic_sky_ms_samples", s.gpuMs},
                    {"environment_ms_samples", e.gpuMs},
                    {"environment_over_sky", e.gpuMsMedian() / s.gpuMsMedian()},
                    {"flip_sky_against_environment", flipMean(e.image, s.image)}});
    savePng(out, tag + "-ibl-sky-" + pathName(decoupled), s.image);
    savePng(out, tag + "-ibl-environment-" + pathName(decoupled), e.image);
  }
  return {{"environment", "procedural sky 256x128 (benchmarks/environment/procedural_sky.hpp)"},
          {"prefilter_ms_median", median(prefilterMs)},
          {"prefilter_ms_samples", prefilterMs},
          {"prefilter_passes_ms_median", {{"environment-downsample", firstFrames.passMedian("environment-downsample")},
                                          {"environment-prefilter", firstFrames.passMedian("environment-prefilter")}}},
          {"first_frame_ms_median", firstFrames.gpuMsMedian()},
          {"rows", rows}};
}

// Bloom on against off (its threshold out of reach) on a set with a glowing box.
nlohmann::json benchBloom(gpu::Device& device, uint32_t width, uint32_t height, int repetitions,
                          const std::filesystem::path& out, const std::string& tag) {
  constexpr float kEmission = 200.0f;  // cd/m^2, above the bloom threshold
  const scene::Scene scene = bloomBenchScene(kEmission);
  std::vector<Variant> variants;
  for (const bool decoupled : {false, true}) {
    variants.push_back({pathName(decoupled) + " bloom", decoupled, scene, {{"exposure", exposure(kBloomEv)}}});
    variants.push_back({pathName(decoupled) + " no bloom", decoupled, scene,
                        {{"exposure", exposure(kBloomEv)}, {"bloom", {{"threshold", 1e30}}}}});
  }
  const auto measured = alternate(device, variants, width, height, repetitions, "bloom");
  nlohmann::json rows = nlohmann::json::array();
  for (const bool decoupled : {false, true}) {
    const Measured& on = measured[decoupled ? 2 : 0];
    const Measured& off = measured[decoupled ? 3 : 1];
    rows.push_back({{"path", pathName(decoupled)},
                    {"bloom_ms_median", on.gpuMsMedian()},
                    {"no_bloom_ms_median", off.gpuMsMedian()},
                    {"bloom_ms_samples", on.gpuMs},
                    {"no_bloom_ms_samples", off.gpuMs},
                    {"bloom_pass_ms_median", on.passMedian("bloom")},
                    {"bloom_over_no_bloom", on.gpuMsMedian() / off.gpuMsMedian()},
                    {"flip_no_bloom_against_bloom", flipMean(on.image, off.image)}});
    savePng(out, tag + "-bloom-" + pathName(decoupled), on.image);
    savePng(out, tag + "-no-bloom-" + pathName(decoupled), off.image);
  }
  return {{"emission", kEmission}, {"rows", rows}};
}

bool runs(const EffectsBenchArgs& args, const std::string& group) {
  return std::find(args.groups.begin(), args.groups.end(), group) != args.groups.end();
}

void printTable(const nlohmann::json& run) {
  std::printf("effects %dx%d, medians of %d alternated rounds (GPU frame ms)\n", run["width"].get<int>(),
              run["height"].get<int>(), run["repetitions"].get<int>());
  if (run.contains("shadows")) {
    std::printf("%-12s %-9s %8s %9s %8s %10s %9s\n", "shadows", "path", "shadowed", "frame ms", "÷ none", "ms/light",
                "FLIP");
    for (const auto& g : run["shadows"])
      for (const auto& r : g["rows"])
        std::printf("%-12s %-9s %8d %9.1f %8.2f %10s %9.4f\n", g["light_type"].get<std::string>().c_str(),
                    g["path"].get<std::string>().c_str(), r["shadowed"].get<int>(), r["frame_ms_median"].get<double>(),
                    r["ratio_to_unshadowed"].get<double>(),
                    r["ms_per_shadowed_light"].is_null()
                        ? "-"
                        : std::to_string(int(std::lround(r["ms_per_shadowed_light"].get<double>()))).c_str(),
                    r["flip_against_all_shadowed"].get<double>());
  }
  if (run.contains("lights")) {
    std::printf("%-7s %-9s %7s %10s %10s %8s %9s %9s\n", "lights", "path", "range", "culled ms", "brute ms",
                "brute÷c", "cull pass", "FLIP");
    for (const auto& r : run["lights"]["rows"])
      std::printf("%-7d %-9s %7.2f %10.1f %10.1f %8.2f %9.2f %9.5f\n", r["lights"].get<int>(),
                  r["path"].get<std::string>().c_str(), r["range"].get<double>(), r["culled_ms_median"].get<double>(),
                  r["brute_force_ms_median"].get<double>(), r["brute_force_over_culled"].get<double>(),
                  r["light_cull_pass_ms_median"].get<double>(), r["flip_culled_against_brute_force"].get<double>());
    for (const auto& [path, from] : run["lights"]["culling_faster_from"].items())
      std::printf("culling faster than brute force (%s): %s\n", path.c_str(),
                  from.is_null() ? "not at the largest count measured" : ("from " + from.dump() + " lights on").c_str());
  }
  if (run.contains("ibl")) {
    const auto& ibl = run["ibl"];
    std::printf("environment prefilter (once): %.1f ms; first frame %.1f ms\n", ibl["prefilter_ms_median"].get<double>(),
                ibl["first_frame_ms_median"].get<double>());
    for (const auto& r : ibl["rows"])
      std::printf("ibl %-9s sky %.1f ms, environment %.1f ms (%.2fx), FLIP sky vs environment %.4f\n",
                  r["path"].get<std::string>().c_str(), r["analytic_sky_ms_median"].get<double>(),
                  r["environment_ms_median"].get<double>(), r["environment_over_sky"].get<double>(),
                  r["flip_sky_against_environment"].get<double>());
  }
  if (run.contains("bloom"))
    for (const auto& r : run["bloom"]["rows"])
      std::printf("bloom %-9s off %.1f ms, on %.1f ms (%.2fx, pass %.1f ms), FLIP off vs on %.4f\n",
                  r["path"].get<std::string>().c_str(), r["no_bloom_ms_median"].get<double>(),
                  r["bloom_ms_median"].get<double>(), r["bloom_over_no_bloom"].get<double>(),
                  r["bloom_pass_ms_median"].get<double>(), r["flip_no_bloom_against_bloom"].get<double>());
}

}  // namespace

void runEffectsBench(gpu::Context& context, gpu::Device& device, const EffectsBenchArgs& args,
                     const std::filesystem::path& out) {
  const nlohmann::json sizeRuns = runPerSceneAndSize({}, args.sizes, [&](const std::string&, uint32_t w, uint32_t h) {
    const std::string tag = std::to_string(w) + "x" + std::to_string(h);
    nlohmann::json run{{"width", w}, {"height", h}, {"repetitions", args.repetitions}};
    if (runs(args, "shadows")) run["shadows"] = benchShadows(device, w, h, args.repetitions, out, tag);
    if (runs(args, "lights")) run["lights"] = benchLights(device, w, h, args.repetitions, args.lightCounts, out, tag);
    if (runs(args, "ibl")) run["ibl"] = benchIbl(device, w, h, args.repetitions, out, tag);
    if (runs(args, "bloom")) run["bloom"] = benchBloom(device, w, h, args.repetitions, out, tag);
    return run;
  });
  const nlohmann::json results{{"machine", machineJson(context)}, {"runs", sizeRuns}};
  writeTextFile(out / "effects.json", "results", results.dump(2) + "\n");
  for (const auto& run : sizeRuns) printTable(run);
  std::printf("wrote %s/effects.json and images\n", out.c_str());
}

}  // namespace sg::app
