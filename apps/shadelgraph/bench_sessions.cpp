#include "bench_sessions.hpp"

#include <builtin_plugins.hpp>
#include <decoupled/decoupled_package.hpp>

#include "bench_materials.hpp"

namespace sg::app {

void BenchSession::make(gpu::Device& device, const scene::Scene& source, std::optional<scene::ShadingMode> mode,
                        const plugins::DecoupledSettings& settings) {
  scene = source;
  auto made = plugins::makeDecoupledRenderer(device, scene, plugins::builtinRegistry(), mode, settings);
  decoupled = std::move(made.shading);
  renderer = std::move(made.renderer);
}

double BenchSession::frameMedian() const { return median(frameMs); }

double BenchSession::passMedian(const std::string& pass) const {
  const auto found = passMs.find(pass);
  return found == passMs.end() ? 0.0 : median(found->second);
}

nlohmann::json BenchSession::passMedians() const { return medians(passMs); }

void alternateFrames(const std::vector<BenchSession*>& sessions, int repetitions) {
  for (int rep = -1; rep < repetitions; ++rep)
    for (BenchSession* session : sessions) {
      auto frame = session->renderer->render(session->view);
      if (rep < 0) continue;  // warm-up
      session->frameMs.push_back(frame.timings.gpuMs);
      for (const auto& p : frame.timings.passes) session->passMs[p.name].push_back(p.gpuMs);
      session->last = std::move(frame);
    }
}

}  // namespace sg::app
