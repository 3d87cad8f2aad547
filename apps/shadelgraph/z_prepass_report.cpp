#include "z_prepass_report.hpp"

#include <cstdio>

namespace sg::app {

std::shared_ptr<passes::ZPrepassChoice> provideZPrepassChoice(render::Renderer& renderer) {
  auto choice = std::make_shared<passes::ZPrepassChoice>();
  renderer.provideState(passes::kZPrepassChoiceState, choice);
  return choice;
}

nlohmann::json zPrepassJson(passes::ZPrepassChoice& choice) {
  const passes::ZPrepassReport& r = choice.collectedReport();
  if (r.reason.empty()) return nullptr;
  nlohmann::json json{{"drawn", r.drawn}, {"measuring", r.measuring}, {"reason", r.reason},
                      {"measurements", r.measurements}};
  if (r.measured) {
    const passes::Overdraw& o = *r.measured;
    // Occlusion-query counts of the measurement frame (drawn with the pre-pass).
    json["overdraw"] = {{"frame", r.measuredFrame},
                        {"triangles", o.triangles},
                        {"fragments_without_prepass", o.depthPassed},
                        {"fragments_with_prepass", o.shaded},
                        {"depth_complexity", o.depthComplexity()},
                        {"textures_per_triangle", o.texturesPerTriangle},
                        {"overdrawn_per_triangle", o.triangles ? double(o.overdrawn()) / double(o.triangles) : 0.0},
                        {"pays", passes::zPrepassPays(o)}};
  }
  return json;
}

void printZPrepass(passes::ZPrepassChoice& choice) {
  const passes::ZPrepassReport& r = choice.collectedReport();
  if (r.reason.empty()) return;
  std::printf("z-prepass: %s, %s", r.drawn ? "drawn" : "not drawn", r.reason.c_str());
  if (r.measured)
    std::printf("; overdraw of frame %llu: %llu fragments without it, %llu with (depth complexity %.2f), %llu triangles",
                (unsigned long long)r.measuredFrame, (unsigned long long)r.measured->depthPassed,
                (unsigned long long)r.measured->shaded, r.measured->depthComplexity(),
                (unsigned long long)r.measured->triangles);
  std::printf("\n");
}

}  // namespace sg::app
