#include "z_prepass_rule.hpp"

#include <cmath>

namespace sg::passes {

bool zPrepassPays(const Overdraw& measured) {
  const double shading = 1.0 + kZPrepassShadingPerTexture * measured.texturesPerTriangle;
  return double(measured.overdrawn()) * shading > kZPrepassFragmentsPerTriangle * double(measured.triangles);
}

bool overdrawStale(const OverdrawView& measured, const OverdrawView& now) {
  if (measured.width != now.width || measured.height != now.height) return true;
  const double a = double(measured.triangles), b = double(now.triangles);
  if (std::abs(a - b) > std::max(a, b) / 8.0) return true;
  double diff = 0.0, norm = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      const double d = double(now.viewProjection[c][r]) - double(measured.viewProjection[c][r]);
      diff += d * d;
      norm += double(measured.viewProjection[c][r]) * double(measured.viewProjection[c][r]);
    }
  return diff > 0.01 * norm;  // (0.1 relative)^2
}

}  // namespace sg::passes
