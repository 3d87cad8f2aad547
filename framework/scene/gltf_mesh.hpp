#pragma once
// Internal to the glTF loader: meshes and their primitives.
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene::detail {

// Fills scene.meshes (one per glTF mesh, same order). Needs scene.materials
// (tangents are generated for primitives whose material has a normal map);
// appends the glTF default material for primitives without one.
// Throws InvalidAsset.
void convertMeshes(const GltfContext& context, Scene& scene);

}  // namespace sg::scene::detail
