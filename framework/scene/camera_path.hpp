#pragma once
// Camera paths for benchmarks and flicker measurements: an orbit around a
// point, or a fly-through through timed keys. Scene files declare them (see
// scene_file.hpp).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/bounds.hpp>
#include <shadelgraph/scene/camera.hpp>

namespace sg::scene {

struct CameraKey {
  float time = 0.0f;  // seconds
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f};
};

struct CameraPath {
  enum class Type { Orbit, Keys };

  std::string name;
  Type type = Type::Orbit;
  // Orbit: the eye circles `center` at `radius`, `height` above it, once every
  // `seconds`, starting on +Z and turning towards +X; it looks at `center`.
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  float height = 0.0f;
  float seconds = 10.0f;
  // Keys: times strictly increasing. Position and target follow Catmull-Rom
  // splines through the keys (knots at the key times, so uneven spacing does
  // not distort speed); before the first and after the last key they hold.
  std::vector<CameraKey> keys;

  // Orbit: one revolution; keys: last key time minus first.
  float duration() const;
};

struct CameraPose {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
};

CameraPose evaluatePose(const CameraPath& path, float seconds);
// World to camera at time `seconds` (right-handed, looking down -Z, +Y up).
glm::mat4 evaluateView(const CameraPath& path, float seconds);
// The perspective camera (yfov 0.8) at a pose, its near and far planes set by
// how far the scene (its world bounds) reaches from the eye.
Camera poseCamera(const CameraPose& pose, const Bounds& sceneBounds);

}  // namespace sg::scene
