#include "camera_controller.hpp"

#include <algorithm>
#include <cmath>

namespace sg::app::view {
namespace {
constexpr float kRadiansPerPixel = 0.008f;
constexpr float kMaxPitch = 1.55f;  // short of straight up or down, where yaw is undefined
}  // namespace

glm::vec3 CameraController::direction() const {
  return {std::cos(pitch_) * -std::sin(yaw_), std::sin(pitch_), std::cos(pitch_) * -std::cos(yaw_)};
}

void CameraController::reset(const scene::Camera& camera, float distance) {
  lens_ = camera;
  const glm::vec3 eye = camera.position();
  const glm::vec3 forward = glm::normalize(-glm::vec3(camera.world[2]));
  pitch_ = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
  yaw_ = std::atan2(-forward.x, -forward.z);
  distance_ = std::max(distance, 1e-3f);
  target_ = eye + forward * distance_;
  speed_ = std::max(distance_, 1e-3f);
}

void CameraController::frame(const scene::Bounds& bounds, float aspect) {
  const scene::Camera framed = scene::frameBounds(bounds, aspect);
  reset(framed, glm::length(bounds.center() - framed.position()));
}

void CameraController::orbit(float dx, float dy) {
  yaw_ -= dx * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ - dy * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void CameraController::look(float dx, float dy) {
  const glm::vec3 eye = target_ - direction() * distance_;
  orbit(dx, dy);
  target_ = eye + direction() * distance_;
}

void CameraController::pan(float dx, float dy, float viewportHeight) {
  const glm::vec3 forward = direction();
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
  const glm::vec3 up = glm::cross(right, forward);
  // A pixel at the target's distance: the target moves with the cursor.
  const float perPixel = 2.0f * distance_ * std::tan(lens_.yfov * 0.5f) / std::max(viewportHeight, 1.0f);
  target_ += (-dx * right + dy * up) * perPixel;
}

void CameraController::zoom(float steps) { distance_ = std::max(distance_ * std::pow(0.85f, steps), 1e-3f); }

void CameraController::fly(float forward, float right, float up, float seconds) {
  const glm::vec3 f = direction();
  const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  target_ += (f * forward + r * right + glm::vec3(0, 1, 0) * up) * speed_ * seconds;
}

scene::Camera CameraController::camera() const {
  scene::Camera c = lens_;
  c.name = "free";
  c.node = -1;
  const glm::vec3 eye = target_ - direction() * distance_;
  c.world = scene::lookAtWorld(eye, target_);
  return c;
}

}  // namespace sg::app::view
