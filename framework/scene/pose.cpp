#include <array>
#include <cmath>

#include <shadelgraph/scene/pose.hpp>

namespace sg::scene {

std::vector<glm::mat4> poseNodes(const Scene& scene, std::span<const int> animations, float t) {
  std::vector<Node> nodes = scene.nodes;
  std::array<float, 4> value{};
  for (const int a : animations) {
    const Animation& animation = scene.animations.at(static_cast<size_t>(a));
    for (const AnimationChannel& channel : animation.channels) {
      if (channel.path == AnimatedPath::Weights) continue;  // poseWeights samples these
      const AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
      Node& node = nodes[static_cast<size_t>(channel.node)];
      const bool rotation = channel.path == AnimatedPath::Rotation;
      sampleAt(sampler, t + animation.timeOffset, rotation, value);
      if (rotation) node.rotation = glm::quat(value[3], value[0], value[1], value[2]);
      else if (channel.path == AnimatedPath::Translation) node.translation = glm::vec3(value[0], value[1], value[2]);
      else node.scale = glm::vec3(value[0], value[1], value[2]);
    }
  }
  std::vector<glm::mat4> world(nodes.size());
  for (size_t n = 0; n < nodes.size(); ++n) {
    const Node& node = nodes[n];
    world[n] = (node.parent < 0 ? node.placement : world[static_cast<size_t>(node.parent)]) * node.local();
  }
  return world;
}

std::vector<std::vector<float>> poseWeights(const Scene& scene, std::span<const int> animations, float t) {
  std::vector<std::vector<float>> weights(scene.nodes.size());
  for (size_t n = 0; n < weights.size(); ++n) weights[n] = scene.nodes[n].weights;
  std::vector<float> value;
  for (const int a : animations) {
    const Animation& animation = scene.animations.at(static_cast<size_t>(a));
    for (const AnimationChannel& channel : animation.channels) {
      if (channel.path != AnimatedPath::Weights) continue;
      const AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
      std::vector<float>& node = weights[static_cast<size_t>(channel.node)];
      if (sampler.width != node.size()) continue;  // not one weight per morph target of the node's mesh
      value.resize(sampler.width);
      sampleAt(sampler, t + animation.timeOffset, false, value);
      node = value;
    }
  }
  return weights;
}

void applyWeights(Scene& scene, std::span<const std::vector<float>> nodeWeights) {
  for (Instance& instance : scene.instances)
    if (instance.node >= 0 && !instance.morphWeights.empty())
      instance.morphWeights = nodeWeights[static_cast<size_t>(instance.node)];
}

namespace {

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

}  // namespace

void applyPose(Scene& scene, std::span<const glm::mat4> nodeWorld) {
  // A pose that overflows (finite keys, huge scales down a deep chain) leaves the object where it was.
  for (Instance& instance : scene.instances)
    if (instance.node >= 0 && finite(nodeWorld[static_cast<size_t>(instance.node)]))
      instance.world = nodeWorld[static_cast<size_t>(instance.node)];
  for (Camera& camera : scene.cameras)
    if (camera.node >= 0 && finite(nodeWorld[static_cast<size_t>(camera.node)]))
      camera.world = nodeWorld[static_cast<size_t>(camera.node)];
}

std::vector<int> allAnimations(const Scene& scene) {
  std::vector<int> all(scene.animations.size());
  for (size_t a = 0; a < all.size(); ++a) all[a] = static_cast<int>(a);
  return all;
}

}  // namespace sg::scene
