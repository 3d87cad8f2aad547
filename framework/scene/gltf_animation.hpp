#pragma once
// Internal to the glTF loader: animations.
#include <vector>

#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene::detail {

// Fills scene.animations from the file. `sceneNodeOf` maps glTF nodes to
// Scene::nodes (convertNodes); channels on nodes outside the scene shown are
// dropped. Throws InvalidAsset on samplers that break the glTF rules (times
// not strictly increasing or not finite, value counts that do not match,
// unknown interpolation); channels with an unknown path, no node, or a node
// given as a matrix are skipped with a warning.
void convertAnimations(const GltfContext& context, const std::vector<int>& sceneNodeOf, Scene& scene);

}  // namespace sg::scene::detail
