#include "animation_player.hpp"

#include <algorithm>
#include <stdexcept>

#include <shadelgraph/scene/pose.hpp>

namespace sg::app {

AnimationPlayer::AnimationPlayer(scene::Scene& scene, const std::string& selection, const std::string& option)
    : scene_(scene) {
  if (selection == "none") return;
  if (selection == "all") {
    animations_ = scene::allAnimations(scene);
    return;
  }
  for (size_t a = 0; a < scene.animations.size(); ++a)
    if (scene.animations[a].name == selection || std::to_string(a) == selection) {
      animations_ = {static_cast<int>(a)};
      return;
    }
  std::string names;
  for (size_t a = 0; a < scene.animations.size(); ++a)
    names += (a ? ", " : "") + std::to_string(a) + " '" + scene.animations[a].name + "'";
  throw std::invalid_argument(option + " " + selection + ": " +
                              (names.empty() ? "the scene has no animations" : "the scene's animations are " + names) +
                              " (or all, none)");
}

scene::Bounds AnimationPlayer::playbackBounds() const {
  float duration = 0.0f;
  for (const int a : animations_) duration = std::max(duration, scene_.animations[size_t(a)].duration());
  scene::Bounds bounds;
  constexpr int kSamples = 32;
  for (int s = 0; s <= kSamples; ++s) {
    const std::vector<glm::mat4> world = scene::poseNodes(scene_, animations_, duration * float(s) / kSamples);
    for (const scene::Instance& instance : scene_.instances) {
      const glm::mat4& m = instance.node >= 0 ? world[size_t(instance.node)] : instance.world;
      bounds.extend(scene::transformBounds(scene_.meshes[size_t(instance.mesh)].bounds, m));
    }
  }
  return bounds;
}

void AnimationPlayer::poseAt(float seconds, render::Renderer& renderer) {
  std::vector<glm::mat4> before(scene_.instances.size());
  for (size_t i = 0; i < before.size(); ++i) before[i] = scene_.instances[i].world;
  scene::applyPose(scene_, scene::poseNodes(scene_, animations_, seconds));
  for (size_t i = 0; i < before.size(); ++i)
    if (scene_.instances[i].world != before[i]) renderer.setObjectTransform(static_cast<uint32_t>(i), scene_.instances[i].world);
}

}  // namespace sg::app
