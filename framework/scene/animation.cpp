#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include <shadelgraph/scene/animation.hpp>

namespace sg::scene {

float Animation::duration() const {
  float last = 0.0f;
  for (const AnimationSampler& s : samplers)
    if (!s.times.empty()) last = std::max(last, s.times.back());
  return last;
}

namespace {

// Values of key k: for CubicSpline, group 0 in-tangent, 1 value, 2 out-tangent.
const float* keyValue(const AnimationSampler& s, size_t k, size_t group = 1) {
  const size_t groups = s.interpolation == Interpolation::CubicSpline ? 3 : 1;
  return s.values.data() + (k * groups + (groups == 3 ? group : 0)) * s.width;
}

void normalizeQuaternion(std::span<float> q) {
  const float length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(length > 0.0f) || !std::isfinite(length)) {
    q[0] = q[1] = q[2] = 0.0f;  // a degenerate key: no rotation rather than NaN
    q[3] = 1.0f;
    return;
  }
  for (float& c : q) c /= length;
}

}  // namespace

void sampleAt(const AnimationSampler& s, float t, bool rotation, std::span<float> out) {
  const size_t keys = s.times.size();
  const size_t width = s.width;
  // The last key at or before t (clamped to the ends).
  const auto next = std::upper_bound(s.times.begin(), s.times.end(), t);
  if (next == s.times.begin() || next == s.times.end() || keys == 1) {
    const size_t k = next == s.times.begin() ? 0 : keys - 1;
    std::copy_n(keyValue(s, k), width, out.begin());
    if (rotation) normalizeQuaternion(out);
    return;
  }
  const auto k1 = static_cast<size_t>(next - s.times.begin());
  const size_t k0 = k1 - 1;
  const float interval = s.times[k1] - s.times[k0];
  const float u = (t - s.times[k0]) / interval;
  switch (s.interpolation) {
    case Interpolation::Step:
      std::copy_n(keyValue(s, k0), width, out.begin());
      break;
    case Interpolation::Linear:
      if (rotation) {
        const float* a = keyValue(s, k0);
        const float* b = keyValue(s, k1);
        // glm::slerp takes the shorter arc and falls back to lerp for nearly equal keys.
        const glm::quat q = glm::slerp(glm::quat(a[3], a[0], a[1], a[2]), glm::quat(b[3], b[0], b[1], b[2]), u);
        out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
      } else {
        const float* a = keyValue(s, k0);
        const float* b = keyValue(s, k1);
        for (size_t c = 0; c < width; ++c) out[c] = a[c] + (b[c] - a[c]) * u;
      }
      break;
    case Interpolation::CubicSpline: {
      // glTF Appendix C: p(u) = h00 v0 + h10 d b0 + h01 v1 + h11 d a1, d = the key interval.
      const float u2 = u * u, u3 = u2 * u;
      const float h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
      const float* v0 = keyValue(s, k0, 1);
      const float* b0 = keyValue(s, k0, 2);
      const float* v1 = keyValue(s, k1, 1);
      const float* a1 = keyValue(s, k1, 0);
      for (size_t c = 0; c < width; ++c)
        out[c] = h00 * v0[c] + h10 * interval * b0[c] + h01 * v1[c] + h11 * interval * a1[c];
      break;
    }
  }
  if (rotation) normalizeQuaternion(out);
}

}  // namespace sg::scene
