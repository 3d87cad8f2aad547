#pragma once
// Rigid motion of a scene object over time, declared per object in scene
// files like camera paths (scene_file.hpp) and given to the default scene's
// gold sphere, so that every multi-frame run exercises moving objects. Time
// 0 is the object's placed pose: frame 0 renders the scene as placed.
#include <vector>

#include <glm/glm.hpp>

namespace sg::scene {

struct ObjectKey {
  float time = 0.0f;            // seconds
  glm::vec3 translation{0.0f};  // offset from the placed pose
};

struct ObjectMotion {
  enum class Type { None, Orbit, Keys };
  Type type = Type::None;
  // Orbit: the object's offset circles in the horizontal plane, `radius`
  // across, once every `seconds`, starting at 0 (the placed pose) and
  // moving towards +Z first.
  float radius = 0.0f;
  float seconds = 10.0f;
  // Keys: offsets through timed keys (Catmull-Rom, as camera keys; held before the first and after the last).
  std::vector<ObjectKey> keys;
  // Both: a turn about the vertical axis through `pivot` (world space, the
  // object's placed origin), this many degrees a second.
  float spinDegreesPerSecond = 0.0f;
  glm::vec3 pivot{0.0f};

  bool moves() const { return type != Type::None || spinDegreesPerSecond != 0.0f; }
};

// The world matrix at `seconds` of an object placed at `placed` (its pose at time 0).
glm::mat4 movedWorld(const ObjectMotion& motion, const glm::mat4& placed, float seconds);

}  // namespace sg::scene
