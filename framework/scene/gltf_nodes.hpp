#pragma once
// Internal to the glTF loader: the node hierarchy, flattened.
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene::detail {

// Walks the default scene (else scene 0, else every root node) and fills
// scene.nodes (parents first), and scene.instances, scene.cameras and
// scene.lights with world transforms. Returns the Scene::nodes index of each
// glTF node (-1: not in the scene shown). Throws InvalidAsset on node cycles,
// nodes with two parents, and references out of range.
std::vector<int> convertNodes(const GltfContext& context, Scene& scene);

}  // namespace sg::scene::detail
