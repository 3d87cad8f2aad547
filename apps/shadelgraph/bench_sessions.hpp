#pragma once
// What the device benches share: one renderer per configuration, set up
// side by side in one process, and frames alternated round-robin across them
// (one warm-up round, then timed rounds), each keeping its samples.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <decoupled/decoupled_shading.hpp>
#include <shadelgraph/gpu/device.hpp>
#include <shadelgraph/render/renderer.hpp>

namespace sg::app {

// One configuration: its scene (the renderer keeps a reference: a session
// must not move once made), renderer, the view its timed frames render, and
// what they measured.
struct BenchSession {
  scene::Scene scene;
  std::shared_ptr<plugins::DecoupledShading> decoupled;
  std::unique_ptr<render::Renderer> renderer;
  render::RenderSettings view;
  std::vector<double> frameMs;                         // GPU span of each timed frame
  std::map<std::string, std::vector<double>> passMs;   // GPU time of each pass in each timed frame
  render::FrameResult last;                            // the last timed frame

  BenchSession() = default;
  BenchSession(const BenchSession&) = delete;
  BenchSession& operator=(const BenchSession&) = delete;

  // `mode`: every object's (empty: each its own, auto by default).
  void make(gpu::Device& device, const scene::Scene& source, std::optional<scene::ShadingMode> mode,
            const plugins::DecoupledSettings& settings = {});
  double frameMedian() const;
  // Median GPU time of a pass (0 when the frames did not run it).
  double passMedian(const std::string& pass) const;
  nlohmann::json passMedians() const;
};

// Renders every session's view round-robin: one untimed warm-up round
// (pipelines, the adjuster, last frame's visibility), then `repetitions`
// rounds whose frames each session keeps.
void alternateFrames(const std::vector<BenchSession*>& sessions, int repetitions);

}  // namespace sg::app
