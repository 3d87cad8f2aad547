#pragma once
// Skinning and morph targets on the CPU: the joint matrices and morph weights
// the GPU skinning pass (passes/skinning) is given each frame, the reference
// it is tested against, and the conservative bounds culling uses while the
// vertices move.
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::scene {

// World-space skinning matrix of each joint of `skin`: nodeWorld[joint] *
// inverseBind. (The GPU pass gets them relative to the object's world
// transform, so that skinned vertices stay in mesh space like every other.)
std::vector<glm::mat4> jointWorldMatrices(const Skin& skin, std::span<const glm::mat4> nodeWorld);

struct DeformedVertex {
  glm::vec3 position;
  glm::vec3 normal;   // unit
  glm::vec4 tangent;  // xyz unit, w the rest handedness
};

// Vertex `v` of `primitive` morphed with `weights` (missing weights count 0),
// then skinned with `joints` (mesh-space matrices; ignored when the primitive
// has no joints or the vertex's weights are all 0). What passes/skinning computes.
DeformedVertex deformVertex(const Primitive& primitive, size_t v, std::span<const glm::mat4> joints,
                            std::span<const float> weights);

// The rest-pose boxes skinning and morphing move, measured once per mesh:
// per joint the box of the vertices it influences, the box of the vertices no
// joint does, and per morph target the box of its position deltas.
struct DeformationBounds {
  std::vector<Bounds> joints;   // by joint index (JOINTS_n value)
  Bounds unskinned;             // vertices without joints, or with all weights 0
  std::vector<Bounds> targets;  // by target index (across the primitives)
};
DeformationBounds deformationBounds(const Mesh& mesh);

// A mesh-space box holding every vertex deformed with `joints` and `weights`:
// each joint's box (grown by the weighted morph deltas) moved by the joint's
// matrix; a skinned vertex is a convex combination of those points.
Bounds deformedBounds(const DeformationBounds& rest, std::span<const glm::mat4> joints, std::span<const float> weights);

// World box of every instance posed with `nodeWorld` and `nodeWeights`
// (poseNodes' and poseWeights' results): deformed objects by deformedBounds.
Bounds posedWorldBounds(const Scene& scene, std::span<const glm::mat4> nodeWorld,
                        std::span<const std::vector<float>> nodeWeights);

}  // namespace sg::scene
