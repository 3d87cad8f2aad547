#pragma once
// glTF 2.0 loading (.gltf and .glb) into a Scene, with tinygltf for parsing and
// stb_image for decoding.
//
// Supported: the default scene's node hierarchy (matrix or TRS), indexed and
// non-indexed triangles, strips and fans (converted to lists), sparse
// accessors, byteStride, POSITION, NORMAL, TANGENT, TEXCOORD_0/1 (float or
// normalized unsigned byte/short), COLOR_0 (vec3/vec4, float or normalized),
// metallic-roughness materials, samplers, KHR_texture_transform,
// KHR_lights_punctual, cameras, and the node extras {"shading": "auto" |
// "decoupled" | "forward"} (inherited by child nodes), and animations
// (scene.animations over scene.nodes; pose.hpp poses them), skins
// (JOINTS_0/WEIGHTS_0, JOINTS_1/WEIGHTS_1, inverse bind matrices) and morph
// targets (POSITION, NORMAL, TANGENT deltas; deformation.hpp). Points and
// lines are skipped with a warning. Triangles of static primitives are
// reordered for the rasterizer (mesh_order.hpp; LoadOptions::meshOrder).
//
// Repairs, each with a warning: flat normals when NORMAL is missing (the
// primitive is de-indexed, as glTF requires), normals of non-unit length are
// renormalized, MikkTSpace tangents are generated when a material has a
// normal map and the primitive has no TANGENT (tangents.hpp; vertices on a
// mirrored UV seam are split), a triangle list whose length is not a multiple of 3 loses
// its last vertices.
//
// Errors (SceneError, "<file>: <what>", naming the JSON pointer where there
// is one): JSON nested deeper than 256 levels, a GLB container that lies
// about its version or lengths, unreadable file, JSON type errors
// (checked before tinygltf, which silently ignores many), references and byte
// ranges checked on the raw JSON (tinygltf keeps indices in int), numbers
// outside float range, coordinates beyond 1e18, non-TRS matrices, tinygltf errors,
// unsupported required extensions, indices or references out of range,
// accessors outside their buffer, wrong accessor types, non-finite or
// zero-length vertex data, node cycles and nodes with two parents, and any
// image a material uses that is missing or cannot be decoded: tinygltf only
// warns about those, but rendering the material without its texture would be
// silently wrong. Every decision and its glTF-Validator class:
// docs/hostile-input.md.
#include <filesystem>

#include <shadelgraph/scene/mesh_order.hpp>
#include <shadelgraph/scene/scene.hpp>
#include <shadelgraph/scene/scene_error.hpp>

namespace sg::scene {

struct LoadOptions {
  // false: textures get width/height from the image header and no pixels
  // (for tools that only need geometry); images are still checked to exist
  // and to be of a format stb_image reads.
  bool decodeImages = true;
  // Triangle and vertex order of static primitives (mesh_order.hpp); all off:
  // the file's order, e.g. for A/B measurements.
  MeshOrderOptions meshOrder;
};

// Throws SceneError.
Scene loadGltf(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace sg::scene
