#pragma once
// Posing a scene at a time of its animations: node transforms sampled from
// the channels, composed down the hierarchy, and handed to what hangs off them.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::scene {

// World transform of every node with `animations` (indices into
// Scene::animations) applied at time `t` seconds; none: the rest pose. When
// two animations drive one property, the later one in `animations` wins.
std::vector<glm::mat4> poseNodes(const Scene& scene, std::span<const int> animations, float t);

// Moves the instances and cameras that hang off nodes to `nodeWorld`
// (poseNodes' result). Lights stay where they were loaded.
void applyPose(Scene& scene, std::span<const glm::mat4> nodeWorld);

// Morph weights of every node (Node::weights, with the Weights channels of
// `animations` sampled at `t`; a channel whose width is not the node's target
// count is ignored).
std::vector<std::vector<float>> poseWeights(const Scene& scene, std::span<const int> animations, float t);

// Sets the morph weights of the instances that hang off nodes to `nodeWeights` (poseWeights' result).
void applyWeights(Scene& scene, std::span<const std::vector<float>> nodeWeights);

// Every animation of the scene, in order: what plays by default.
std::vector<int> allAnimations(const Scene& scene);

}  // namespace sg::scene
