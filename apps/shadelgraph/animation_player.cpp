#include "animation_player.hpp"

#include <algorithm>
#include <stdexcept>

#include <shadelgraph/scene/deformation.hpp>
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
    const float t = duration * float(s) / kSamples;
    bounds.extend(scene::posedWorldBounds(scene_, scene::poseNodes(scene_, animations_, t),
                                          scene::poseWeights(scene_, animations_, t)));
  }
  return bounds;
}

void AnimationPlayer::poseAt(float seconds, render::Renderer& renderer) {
  std::vector<glm::mat4> before(scene_.instances.size());
  for (size_t i = 0; i < before.size(); ++i) before[i] = scene_.instances[i].world;
  const std::vector<glm::mat4> world = scene::poseNodes(scene_, animations_, seconds);
  scene::applyPose(scene_, world);
  scene::applyWeights(scene_, scene::poseWeights(scene_, animations_, seconds));
  for (size_t i = 0; i < before.size(); ++i) {
    const scene::Instance& instance = scene_.instances[i];
    const auto index = static_cast<uint32_t>(i);
    if (instance.world != before[i]) renderer.setObjectTransform(index, instance.world);
    if (!renderer.gpuScene().deformation().deformed(index)) continue;
    const std::vector<glm::mat4> joints =
        instance.skin >= 0 ? scene::jointWorldMatrices(scene_.skins[size_t(instance.skin)], world) : std::vector<glm::mat4>{};
    renderer.setObjectDeformation(index, joints, instance.morphWeights);
  }
}

}  // namespace sg::app
