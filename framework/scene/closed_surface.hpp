#pragma once
// Is a triangle mesh the closed, outward-facing surface of a solid? Then its
// back faces can never be seen from outside it, so a renderer may cull them
// even for a double-sided material (render/scene_view.hpp).
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace sg::scene {

// True when, after welding vertices with bitwise-equal positions (seams that
// split normals or UVs do not open the surface), every edge of a non-degenerate
// triangle is used exactly once in each direction (closed and consistently
// wound) and every edge-connected part encloses a positive signed volume
// (counter-clockwise seen from outside). Linear in the size of the mesh but for
// sorting each vertex's few edges.
bool isClosedSurface(std::span<const glm::vec3> positions, std::span<const uint32_t> indices);

}  // namespace sg::scene
