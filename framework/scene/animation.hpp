#pragma once
// glTF animations: keyframe samplers that drive the translation, rotation,
// scale and morph weights of nodes (glTF 2.0 §3.11 and Appendix C).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sg::scene {

enum class Interpolation { Step, Linear, CubicSpline };
enum class AnimatedPath { Translation, Rotation, Scale, Weights };

// Keyframes. `times` are finite and strictly increasing (at least one);
// `values` holds `width` floats per key (3: translation or scale, 4: a
// rotation quaternion x, y, z, w; the morph target count: weights), and for
// CubicSpline three groups per key: in-tangent, value, out-tangent.
struct AnimationSampler {
  std::vector<float> times;
  std::vector<float> values;
  uint32_t width = 0;
  Interpolation interpolation = Interpolation::Linear;
};

struct AnimationChannel {
  int node = -1;  // index into Scene::nodes
  AnimatedPath path = AnimatedPath::Translation;
  int sampler = 0;  // index into its Animation::samplers
};

struct Animation {
  std::string name;
  std::vector<AnimationSampler> samplers;
  std::vector<AnimationChannel> channels;
  float timeOffset = 0.0f;  // seconds into its clock at time 0 (a scene file's "timeOffset")

  // The last keyframe time of any sampler (0 without samplers).
  float duration() const;
};

// The sampler's value at time `t` into `out` (width floats). Before the first
// key and after the last the end values hold. Linear rotations are slerped
// along the shorter arc; CubicSpline uses the Hermite spline with tangents
// scaled by the key interval. Rotations come out unit length.
void sampleAt(const AnimationSampler& sampler, float t, bool rotation, std::span<float> out);

}  // namespace sg::scene
