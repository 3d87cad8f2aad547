#include <algorithm>
#include <cmath>
#include <numbers>

#include <shadelgraph/scene/camera.hpp>
#include <shadelgraph/scene/camera_path.hpp>
#include <shadelgraph/scene/catmull_rom.hpp>

namespace sg::scene {
namespace {

CameraPose evaluateKeys(const std::vector<CameraKey>& keys, float time) {
  if (keys.empty()) return {};
  if (keys.size() == 1 || time <= keys.front().time) return {keys.front().position, keys.front().target};
  if (time >= keys.back().time) return {keys.back().position, keys.back().target};
  const auto next = std::upper_bound(keys.begin(), keys.end(), time,
                                     [](float value, const CameraKey& key) { return value < key.time; });
  const size_t i = static_cast<size_t>(next - keys.begin()) - 1;  // keys[i].time <= time < keys[i + 1].time
  const CameraKey& k1 = keys[i];
  const CameraKey& k2 = keys[i + 1];
  // Missing neighbours at the ends are mirrored through the end key.
  const auto neighbour = [&](size_t index, const CameraKey& end, const CameraKey& inner, bool exists) {
    if (exists) return keys[index];
    return CameraKey{2.0f * end.time - inner.time, 2.0f * end.position - inner.position, 2.0f * end.target - inner.target};
  };
  const CameraKey k0 = neighbour(i - (i > 0 ? 1 : 0), k1, k2, i > 0);
  const CameraKey k3 = neighbour(i + 2, k2, k1, i + 2 < keys.size());
  const float t[4] = {k0.time, k1.time, k2.time, k3.time};
  const glm::vec3 positions[4] = {k0.position, k1.position, k2.position, k3.position};
  const glm::vec3 targets[4] = {k0.target, k1.target, k2.target, k3.target};
  return {catmullRom(positions, t, time), catmullRom(targets, t, time)};
}

}  // namespace

float CameraPath::duration() const {
  if (type == Type::Orbit) return seconds;
  return keys.empty() ? 0.0f : keys.back().time - keys.front().time;
}

CameraPose evaluatePose(const CameraPath& path, float seconds) {
  if (path.type == CameraPath::Type::Keys) return evaluateKeys(path.keys, seconds);
  const float angle = path.seconds > 0.0f ? 2.0f * std::numbers::pi_v<float> * seconds / path.seconds : 0.0f;
  const glm::vec3 offset{path.radius * std::sin(angle), path.height, path.radius * std::cos(angle)};
  return {path.center + offset, path.center};
}

glm::mat4 evaluateView(const CameraPath& path, float seconds) {
  const CameraPose pose = evaluatePose(path, seconds);
  return glm::inverse(lookAtWorld(pose.position, pose.target));
}

Camera poseCamera(const CameraPose& pose, const Bounds& sceneBounds) {
  Camera camera{.name = "path", .yfov = 0.8f};
  camera.world = lookAtWorld(pose.position, pose.target);
  const float reach = glm::distance(pose.position, sceneBounds.center()) + sceneBounds.radius();
  camera.znear = std::max(reach * 1e-3f, 1e-3f);
  camera.zfar = reach * 1.5f;
  return camera;
}

}  // namespace sg::scene
