#pragma once
// Cameras: glTF cameras placed by their node, or framed around a scene.
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include <shadelgraph/scene/bounds.hpp>

namespace sg::scene {

enum class Projection { Perspective, Orthographic };

struct Camera {
  std::string name;
  Projection projection = Projection::Perspective;
  float yfov = 0.8f;                 // perspective: vertical field of view, radians
  std::optional<float> aspectRatio;  // perspective: as authored; projections use the viewport's
  float xmag = 1.0f;                 // orthographic: half width as authored; projections use ymag × aspect
  float ymag = 1.0f;                 // orthographic: half height
  float znear = 0.1f;
  std::optional<float> zfar;  // absent = infinite (perspective only)
  glm::mat4 world{1.0f};      // camera to world; the camera looks down its -Z, +Y up
  int node = -1;              // the glTF node it hangs off (Scene::nodes), -1: none

  glm::vec3 position() const { return glm::vec3(world[3]); }
  // World to camera. Scale in `world` is removed first (glTF says camera
  // nodes should have none, but files have it).
  glm::mat4 view() const;
  // Right-handed, clip depth in [0, 1] (near -> 0), clip +Y up: a Vulkan
  // caller flips Y in the viewport. Keeps the vertical field of view (ymag)
  // and takes the width from `viewportAspect`, never from aspectRatio/xmag:
  // an output of another shape sees more or less sideways, never stretched.
  glm::mat4 projectionMatrix(float viewportAspect) const;
};

// A perspective camera that sees all of `sceneBounds` (its bounding sphere fits
// the narrower field of view), looking at its center from the front (+Z) and a
// little above, for scenes without a camera of their own.
Camera frameBounds(const Bounds& sceneBounds, float aspect);

// Camera-to-world matrix of an eye at `eye` looking at `target`, +Y up when
// possible (another up is chosen when looking straight up or down).
glm::mat4 lookAtWorld(const glm::vec3& eye, const glm::vec3& target);

}  // namespace sg::scene
