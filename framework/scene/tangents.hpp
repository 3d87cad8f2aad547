#pragma once
// MikkTSpace tangents, which glTF requires when a file has a normal map and no
// TANGENT. Implemented from Mikkelsen's description ("Simulation of Wrinkled
// Surfaces Revisited", 2008, and the mikktspace.h notes); Debian packages no
// MikkTSpace library. In short:
//   - corners with equal position, normal and UV are one vertex (welded);
//   - each triangle has a unit dP/du and dP/dv and an orientation (the sign of
//     its UV area); triangles without a UV gradient join whatever group reaches them;
//   - at each vertex, the triangles reachable from one another across shared
//     edges with the same orientation form a group;
//   - a group's tangent is the sum of its triangles' dP/du, each projected onto
//     the vertex normal's plane, normalized and weighted by the corner's angle;
//   - the handedness is the group's orientation.
// A vertex whose corners fall into different groups (a mirrored UV seam)
// needs two tangents: addTangents splits it.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::scene {

// One tangent per corner (indices.size() entries): xyz unit and perpendicular
// to the normal, w = +1 or -1 such that bitangent = cross(normal, xyz) * w is
// the image's up (glTF's UV origin is the image's top-left, normal maps are +Y
// up). Corners that no triangle with a UV gradient reaches get some unit
// tangent perpendicular to the normal and w = +1.
std::vector<glm::vec4> cornerTangents(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                      std::span<const glm::vec2> uvs, std::span<const uint32_t> indices);

// Fills `primitive.tangents` from cornerTangents over UV set `uvSet`, splitting
// vertices whose corners need different tangents (every attribute is copied).
// Returns the number of vertices added.
size_t addTangents(Primitive& primitive, int uvSet);

}  // namespace sg::scene
