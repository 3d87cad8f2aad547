#include <shadelgraph/scene/object_motion.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/catmull_rom.hpp>

namespace sg::scene {
namespace {

glm::vec3 keyOffset(const std::vector<ObjectKey>& keys, float time) {
  if (keys.empty()) return glm::vec3(0.0f);
  if (keys.size() == 1 || time <= keys.front().time) return keys.front().translation;
  if (time >= keys.back().time) return keys.back().translation;
  const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                     [](float value, const ObjectKey& key) { return value < key.time; });
  const size_t i = static_cast<size_t>(next - keys.begin()) - 1;
  const ObjectKey& k1 = keys[i];
  const ObjectKey& k2 = keys[i + 1];
  // Missing neighbours at the ends are mirrored through the end key (as camera keys).
  const ObjectKey k0 = i > 0 ? keys[i - 1] : ObjectKey{2.0f * k1.time - k2.time, 2.0f * k1.translation - k2.translation};
  const ObjectKey k3 =
      i + 2 < keys.size() ? keys[i + 2] : ObjectKey{2.0f * k2.time - k1.time, 2.0f * k2.translation - k1.translation};
  const float t[4] = {k0.time, k1.time, k2.time, k3.time};
  const glm::vec3 p[4] = {k0.translation, k1.translation, k2.translation, k3.translation};
  return catmullRom(p, t, time);
}

}  // namespace

glm::mat4 movedWorld(const ObjectMotion& motion, const glm::mat4& placed, float seconds) {
  // Time 0 is exactly the placed pose (no rounding through sin/cos and a pivot).
  if (!motion.moves() || seconds == 0.0f) return placed;
  glm::vec3 offset(0.0f);
  if (motion.type == ObjectMotion::Type::Orbit && motion.seconds > 0.0f) {
    const float angle = 2.0f * std::numbers::pi_v<float> * seconds / motion.seconds;
    offset = {motion.radius * (std::cos(angle) - 1.0f), 0.0f, motion.radius * std::sin(angle)};
  } else if (motion.type == ObjectMotion::Type::Keys) {
    offset = keyOffset(motion.keys, seconds);
  }
  glm::mat4 world = placed;
  if (motion.spinDegreesPerSecond != 0.0f) {
    const glm::mat4 spin = glm::rotate(glm::mat4(1.0f), glm::radians(motion.spinDegreesPerSecond * seconds), {0, 1, 0});
    world = glm::translate(glm::mat4(1.0f), motion.pivot) * spin * glm::translate(glm::mat4(1.0f), -motion.pivot) * world;
  }
  return glm::translate(glm::mat4(1.0f), offset) * world;
}

}  // namespace sg::scene
