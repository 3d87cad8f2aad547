#pragma once
// Which object is under a pixel: the camera's ray through the pixel's centre
// against every instance's triangles (CPU, on the scene's own arrays).
#include <optional>

#include <shadelgraph/scene/scene.hpp>

namespace sg::app::view {

// The nearest instance hit by the ray through pixel (x, y) of a width x height view.
std::optional<uint32_t> pickObject(const scene::Scene& scene, const std::vector<glm::mat4>& worlds,
                                   const scene::Camera& camera, uint32_t width, uint32_t height, double x, double y);

}  // namespace sg::app::view
