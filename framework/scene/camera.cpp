#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/camera.hpp>

namespace sg::scene {

glm::mat4 Camera::view() const {
  glm::mat4 rigid = world;
  for (int axis = 0; axis < 3; ++axis) {
    const glm::vec3 column{world[axis]};
    const float length = glm::length(column);
    if (length > 0.0f) rigid[axis] = glm::vec4(column / length, 0.0f);
  }
  return glm::inverse(rigid);
}

glm::mat4 Camera::projectionMatrix(float viewportAspect) const {
  // The viewport's aspect always wins over the camera's own (glTF `aspectRatio`,
  // `xmag`): the vertical extent is kept and the horizontal one follows the
  // output, so a camera authored for 1:1 shows more, not a stretched image, at 16:9.
  const float aspect = viewportAspect;
  if (projection == Projection::Orthographic) {
    const float halfWidth = ymag * aspect;
    return glm::orthoRH_ZO(-halfWidth, halfWidth, -ymag, ymag, znear, zfar.value_or(znear + 1000.0f));
  }
  if (zfar) return glm::perspectiveRH_ZO(yfov, aspect, znear, *zfar);
  // Infinite far plane with [0, 1] depth: perspectiveRH_ZO in the limit far -> infinity.
  const float f = 1.0f / std::tan(yfov * 0.5f);
  glm::mat4 m(0.0f);
  m[0][0] = f / aspect;
  m[1][1] = f;
  m[2][2] = -1.0f;
  m[2][3] = -1.0f;
  m[3][2] = -znear;
  return m;
}

glm::mat4 lookAtWorld(const glm::vec3& eye, const glm::vec3& target) {
  glm::vec3 forward = target - eye;
  if (glm::length(forward) <= 0.0f) forward = glm::vec3(0.0f, 0.0f, -1.0f);
  forward = glm::normalize(forward);
  const glm::vec3 up = std::abs(forward.y) > 0.999f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::inverse(glm::lookAtRH(eye, eye + forward, up));
}

Camera frameBounds(const Bounds& sceneBounds, float aspect) {
  Camera camera;
  camera.name = "framed";
  camera.projection = Projection::Perspective;
  camera.yfov = glm::radians(45.0f);
  if (sceneBounds.empty()) {
    camera.znear = 0.1f;
    camera.zfar = 100.0f;
    camera.world = lookAtWorld(glm::vec3(0.0f, 0.0f, 5.0f), glm::vec3(0.0f));
    return camera;
  }
  const glm::vec3 center = sceneBounds.center();
  const float radius = std::max(sceneBounds.radius(), 1e-4f);
  // The sphere fits when its angular radius is within half of the narrower fov.
  const float xfov = 2.0f * std::atan(std::tan(camera.yfov * 0.5f) * std::max(aspect, 1e-4f));
  const float halfFov = 0.5f * std::min(camera.yfov, xfov);
  const float distance = radius / std::sin(halfFov) * 1.05f;  // 5% margin
  const glm::vec3 direction = glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f));
  camera.world = lookAtWorld(center + direction * distance, center);
  camera.znear = std::max((distance - radius) * 0.5f, distance * 1e-4f);
  camera.zfar = (distance + radius) * 1.5f;
  return camera;
}

}  // namespace sg::scene
