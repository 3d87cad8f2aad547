#pragma once
// Tangent generation for normal mapping.
//
// NOT MikkTSpace. glTF says tangents a file leaves out should be MikkTSpace
// tangents, but Debian packages no MikkTSpace library; this is the classic
// per-triangle UV-gradient method (Lengyel 2001): each triangle's dP/du and
// dP/dv, weighted by its area, are summed at its vertices; each vertex tangent
// is then Gram-Schmidt orthogonalized against the normal, and w records
// whether the UV mapping is mirrored. On smooth, unmirrored charts the
// result matches MikkTSpace closely; at seams where a vertex is shared by
// triangles of different orientation it averages differently, so baked
// normal maps may show faint seams there.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace sg::scene {

// One tangent per vertex: xyz unit and perpendicular to the normal, w = +1 or
// -1 such that bitangent = cross(normal, xyz) * w points towards decreasing v
// (glTF's UV origin is the image's top-left, and normal maps are +Y up), as
// glTF defines. Vertices whose triangles have no usable UV gradient get any
// unit tangent perpendicular to the normal and w = +1.
std::vector<glm::vec4> generateTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                        std::span<const glm::vec2> uvs, std::span<const uint32_t> indices);

}  // namespace sg::scene
