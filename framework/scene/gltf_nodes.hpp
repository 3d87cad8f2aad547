#pragma once
// Internal to the glTF loader: the node hierarchy, flattened.
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene::detail {

// Walks the default scene (else scene 0, else every root node) and fills
// scene.instances, scene.cameras and scene.lights with world transforms.
// Throws InvalidAsset on node cycles, nodes with two parents, and
// references out of range.
void convertNodes(const GltfContext& context, Scene& scene);

}  // namespace sg::scene::detail
