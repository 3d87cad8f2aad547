#include <shadelgraph/scene/deformation.hpp>

#include <algorithm>

namespace sg::scene {
namespace {

float weightOf(std::span<const float> weights, size_t target) { return target < weights.size() ? weights[target] : 0.0f; }

// The skinning matrix of one vertex; nullopt-like identity flag when it has no influence.
bool skinMatrix(const Primitive& p, size_t v, std::span<const glm::mat4> joints, glm::mat4& out) {
  if (!p.skinned() || joints.empty()) return false;
  glm::mat4 sum(0.0f);
  float total = 0.0f;
  const auto add = [&](const glm::uvec4& j, const glm::vec4& w) {
    for (int i = 0; i < 4; ++i) {
      if (w[i] == 0.0f) continue;
      const size_t joint = std::min<size_t>(j[i], joints.size() - 1);  // the loader checked the range
      sum += w[i] * joints[joint];
      total += w[i];
    }
  };
  add(p.joints0[v], p.weights0[v]);
  if (!p.joints1.empty()) add(p.joints1[v], p.weights1[v]);
  if (total == 0.0f) return false;
  out = sum;
  return true;
}

}  // namespace

std::vector<glm::mat4> jointWorldMatrices(const Skin& skin, std::span<const glm::mat4> nodeWorld) {
  std::vector<glm::mat4> out(skin.joints.size());
  for (size_t j = 0; j < out.size(); ++j) out[j] = nodeWorld[static_cast<size_t>(skin.joints[j])] * skin.inverseBindMatrices[j];
  return out;
}

DeformedVertex deformVertex(const Primitive& p, size_t v, std::span<const glm::mat4> joints, std::span<const float> weights) {
  glm::vec3 position = p.positions[v];
  glm::vec3 normal = p.normals.empty() ? glm::vec3(0, 1, 0) : p.normals[v];
  glm::vec4 tangent = p.tangents.empty() ? glm::vec4(1, 0, 0, 1) : p.tangents[v];
  for (size_t t = 0; t < p.targets.size(); ++t) {
    const float w = weightOf(weights, t);
    const MorphTarget& target = p.targets[t];
    if (!target.positions.empty()) position += w * target.positions[v];
    if (!target.normals.empty()) normal += w * target.normals[v];
    if (!target.tangents.empty()) tangent += glm::vec4(w * target.tangents[v], 0.0f);
  }
  glm::mat4 m;
  if (skinMatrix(p, v, joints, m)) {
    position = glm::vec3(m * glm::vec4(position, 1.0f));
    normal = glm::transpose(glm::inverse(glm::mat3(m))) * normal;
    tangent = glm::vec4(glm::mat3(m) * glm::vec3(tangent), tangent.w);
  }
  const auto unit = [](glm::vec3 x, glm::vec3 fallback) {
    const float length = glm::length(x);
    return length > 1e-12f ? x / length : fallback;
  };
  return {position, unit(normal, glm::vec3(0, 1, 0)), glm::vec4(unit(glm::vec3(tangent), glm::vec3(1, 0, 0)), tangent.w)};
}

DeformationBounds deformationBounds(const Mesh& mesh) {
  DeformationBounds out;
  for (const Primitive& p : mesh.primitives) {
    if (out.targets.size() < p.targets.size()) out.targets.resize(p.targets.size());
    for (size_t t = 0; t < p.targets.size(); ++t) {
      for (const glm::vec3& d : p.targets[t].positions) out.targets[t].extend(d);
      if (p.targets[t].positions.empty() || out.targets[t].empty()) out.targets[t].extend(glm::vec3(0.0f));
    }
    for (size_t v = 0; v < p.positions.size(); ++v) {
      bool influenced = false;
      const auto add = [&](const glm::uvec4& j, const glm::vec4& w) {
        for (int i = 0; i < 4; ++i) {
          if (w[i] == 0.0f) continue;
          if (out.joints.size() <= j[i]) out.joints.resize(j[i] + 1);
          out.joints[j[i]].extend(p.positions[v]);
          influenced = true;
        }
      };
      if (p.skinned()) {
        add(p.joints0[v], p.weights0[v]);
        if (!p.joints1.empty()) add(p.joints1[v], p.weights1[v]);
      }
      if (!influenced) out.unskinned.extend(p.positions[v]);
    }
  }
  return out;
}

Bounds deformedBounds(const DeformationBounds& rest, std::span<const glm::mat4> joints, std::span<const float> weights) {
  // The weighted morph deltas' box (a negative weight flips a target's box).
  glm::vec3 grow0(0.0f), grow1(0.0f);
  for (size_t t = 0; t < rest.targets.size(); ++t) {
    const float w = weightOf(weights, t);
    const glm::vec3 a = w * rest.targets[t].min, b = w * rest.targets[t].max;
    grow0 += glm::min(a, b);
    grow1 += glm::max(a, b);
  }
  const auto grown = [&](const Bounds& box) {
    Bounds out = box;
    if (!out.empty()) {
      out.min += grow0;
      out.max += grow1;
    }
    return out;
  };
  Bounds out = grown(rest.unskinned);
  for (size_t j = 0; j < rest.joints.size(); ++j) {
    if (rest.joints[j].empty()) continue;
    const glm::mat4 m = j < joints.size() ? joints[j] : glm::mat4(1.0f);
    out.extend(transformBounds(grown(rest.joints[j]), m));
  }
  return out;
}

Bounds posedWorldBounds(const Scene& scene, std::span<const glm::mat4> nodeWorld,
                        std::span<const std::vector<float>> nodeWeights) {
  Bounds bounds;
  for (const Instance& instance : scene.instances) {
    const glm::mat4& m = instance.node >= 0 ? nodeWorld[static_cast<size_t>(instance.node)] : instance.world;
    const Mesh& mesh = scene.meshes[static_cast<size_t>(instance.mesh)];
    if (!mesh.deformable()) {
      bounds.extend(transformBounds(mesh.bounds, m));
      continue;
    }
    // Skinned vertices follow their joints (as mesh-space matrices), morphed ones their weights.
    std::vector<glm::mat4> joints;
    if (instance.skin >= 0)
      for (const glm::mat4& joint : jointWorldMatrices(scene.skins[static_cast<size_t>(instance.skin)], nodeWorld))
        joints.push_back(glm::inverse(m) * joint);
    const std::vector<float>& w = instance.node >= 0 ? nodeWeights[static_cast<size_t>(instance.node)] : instance.morphWeights;
    bounds.extend(transformBounds(deformedBounds(deformationBounds(mesh), joints, w), m));
  }
  return bounds;
}

}  // namespace sg::scene
