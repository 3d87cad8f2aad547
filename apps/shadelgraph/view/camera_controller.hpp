#pragma once
// The viewer's free camera: orbit about a target (drag), pan (right or middle
// drag), zoom (wheel), fly (W A S D, Q E down and up; in fly mode a drag
// turns the view about the eye). Starts from, and can be reset to, any scene camera.
#include <glm/glm.hpp>

#include <shadelgraph/scene/bounds.hpp>
#include <shadelgraph/scene/camera.hpp>

namespace sg::app::view {

class CameraController {
 public:
  // Takes the eye, direction and lens of `camera`; orbits a point `distance` ahead.
  void reset(const scene::Camera& camera, float distance);
  // Frames `bounds` (the F key) at the viewport's aspect.
  void frame(const scene::Bounds& bounds, float aspect);

  void orbit(float dxPixels, float dyPixels);
  void pan(float dxPixels, float dyPixels, float viewportHeight);
  void zoom(float steps);
  // In fly mode: turn about the eye.
  void look(float dxPixels, float dyPixels);
  // Fly: move along the view (forward), sideways (right) and up, in units of the scene's size a second.
  void fly(float forward, float right, float up, float seconds);

  bool flyMode = false;
  scene::Camera camera() const;

 private:
  glm::vec3 direction() const;
  glm::vec3 target_{0.0f};
  float distance_ = 1.0f;
  float yaw_ = 0.0f, pitch_ = 0.0f;  // radians; yaw 0 looks down -Z
  float speed_ = 1.0f;               // scene size: fly speed
  scene::Camera lens_;               // projection, near and far of the camera reset from
};

}  // namespace sg::app::view
