#pragma once
// Is a bounding sphere (xyz centre, w radius) at least partly inside the view
// frustum of a world-to-clip matrix (Vulkan clip space, depth 0..w)?
#include <cstdint>

#include <glm/glm.hpp>

#include <shadelgraph/scene/bounds.hpp>

namespace sg::render {

bool sphereInFrustum(const glm::mat4& viewProjection, const glm::vec4& sphere);

// Is the sphere wholly beyond the near plane (so the camera is outside it and
// near clipping cannot cut into what it holds)?
bool sphereBeyondNearPlane(const glm::mat4& viewProjection, const glm::vec4& sphere);

// The pixels a world box can cover on a width x height output drawn with the
// renderer's flipped viewport (PassContext::beginRendering: clip y = w at row 0): x0, y0, x1, y1, end
// exclusive, clamped to the output (empty: x1 <= x0 or y1 <= y0); the whole
// output when a corner is behind the eye (its projection wraps). Conservative:
// the projected corners' rectangle, widened by a pixel.
glm::ivec4 boxScreenRect(const glm::mat4& viewProjection, const scene::Bounds& box, uint32_t width, uint32_t height);

}  // namespace sg::render
