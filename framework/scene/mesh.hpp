#pragma once
// Triangle geometry as plain CPU arrays, ready for upload.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/bounds.hpp>

namespace sg::scene {

// One draw: an indexed triangle list with one material. Every attribute array
// is either empty (absent) or has one entry per vertex. The loader always
// fills positions, normals and indices (non-indexed input gets 0..n-1; strips
// and fans are converted to lists), so consumers need only one draw path.
struct Primitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   // unit length
  std::vector<glm::vec4> tangents;  // xyz unit, w = handedness (+1/-1): bitangent = cross(normal, xyz) * w
  std::vector<glm::vec2> uv0;       // TEXCOORD_0, glTF convention: origin at the image's top-left
  std::vector<glm::vec2> uv1;       // TEXCOORD_1
  std::vector<glm::vec4> colors;    // COLOR_0, linear RGBA (vec3 input gets alpha 1)
  std::vector<uint32_t> indices;    // three per triangle, counter-clockwise front faces
  int material = 0;                 // always a valid index into Scene::materials
  Bounds bounds;                    // of positions, in mesh space

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return indices.size() / 3; }
  const std::vector<glm::vec2>& uvs(int set) const { return set == 1 ? uv1 : uv0; }
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  Bounds bounds;  // union of the primitives' bounds

  size_t triangleCount() const {
    size_t count = 0;
    for (const Primitive& primitive : primitives) count += primitive.triangleCount();
    return count;
  }
};

}  // namespace sg::scene
