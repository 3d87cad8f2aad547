#pragma once
// Is a bounding sphere (xyz centre, w radius) at least partly inside the view
// frustum of a world-to-clip matrix (Vulkan clip space, depth 0..w)?
#include <glm/glm.hpp>

namespace sg::render {

bool sphereInFrustum(const glm::mat4& viewProjection, const glm::vec4& sphere);

// Is the sphere wholly beyond the near plane (so the camera is outside it and
// near clipping cannot cut into what it holds)?
bool sphereBeyondNearPlane(const glm::mat4& viewProjection, const glm::vec4& sphere);

}  // namespace sg::render
