#pragma once
// Triangle geometry as plain CPU arrays, ready for upload.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/bounds.hpp>

namespace sg::scene {

// One morph target of a primitive: per-vertex deltas added with the target's
// weight (glTF 2.0 §3.7.2.2). Each array is empty (absent) or one per vertex.
struct MorphTarget {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec3> tangents;  // xyz only: the handedness does not morph
};

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
  // Skinning (glTF JOINTS_n / WEIGHTS_n): four influences per set, joint
  // indices into the instance's Skin::joints. Set 1 is empty unless the file
  // has JOINTS_1; weights of a vertex sum to 1 (normalized at load) or are all 0.
  std::vector<glm::uvec4> joints0, joints1;
  std::vector<glm::vec4> weights0, weights1;
  std::vector<MorphTarget> targets;  // morph targets, weighted by the instance's morph weights
  int material = 0;                 // always a valid index into Scene::materials
  Bounds bounds;                    // of positions, in mesh space
  // The closed, outward-wound surface of a solid (closed_surface.hpp): its back
  // faces are hidden from outside. Set by the glTF loader; false: not known.
  bool closedSurface = false;
  // TEXCOORD_1 is a chart made for decoupled shading (shadel::autoChartMesh),
  // not the file's: its shadels sample the textures off their texel grid.
  bool automaticChart = false;

  size_t vertexCount() const { return positions.size(); }
  size_t triangleCount() const { return indices.size() / 3; }
  const std::vector<glm::vec2>& uvs(int set) const { return set == 1 ? uv1 : uv0; }
  bool skinned() const { return !joints0.empty(); }
  bool morphed() const { return !targets.empty(); }
};

// Calls f(array) on each per-vertex array skinning and morphing add (joints,
// weights, every target's deltas), for code that splits or copies vertices.
template <class F>
void forEachDeformationAttribute(Primitive& p, F&& f) {
  f(p.joints0);
  f(p.joints1);
  f(p.weights0);
  f(p.weights1);
  for (MorphTarget& target : p.targets) {
    f(target.positions);
    f(target.normals);
    f(target.tangents);
  }
}

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  Bounds bounds;  // union of the primitives' bounds (rest pose)
  std::vector<float> weights;  // default morph weights (one per target of its primitives; empty: none)

  size_t triangleCount() const {
    size_t count = 0;
    for (const Primitive& primitive : primitives) count += primitive.triangleCount();
    return count;
  }
  // Some primitive has joints or morph targets: its vertices move on the GPU each frame.
  bool deformable() const {
    for (const Primitive& primitive : primitives)
      if (primitive.skinned() || primitive.morphed()) return true;
    return false;
  }
};

}  // namespace sg::scene
