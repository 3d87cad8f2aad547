#pragma once
// Plays a scene's glTF animations on a renderer: poses the scene at a time
// and moves the renderer's objects that the pose moved.
#include <string>
#include <vector>

#include <shadelgraph/render/renderer.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::app {

class AnimationPlayer {
 public:
  // selection: "all", "none", an animation's index or its name; anything
  // else throws std::invalid_argument naming `option` and the animations there are.
  AnimationPlayer(scene::Scene& scene, const std::string& selection, const std::string& option = "--animation");

  bool playing() const { return !animations_.empty(); }
  // Poses the scene at `seconds` and hands every moved object to `renderer`,
  // and every skinned or morphed object its joint matrices and morph weights.
  void poseAt(float seconds, render::Renderer& renderer);
  // World bounds of the scene over the whole playback (sampled), to frame it once.
  scene::Bounds playbackBounds() const;

 private:
  scene::Scene& scene_;
  std::vector<int> animations_;
};

}  // namespace sg::app
