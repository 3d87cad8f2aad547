#pragma once
// Internal to the glTF loader: skins.
#include <vector>

#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene::detail {

// Fills scene.skins (one per glTF skin, same order: Instance::skin is the
// file's index) from the nodes convertNodes kept (`sceneNodeOf`). Throws
// InvalidAsset when a joint is not in the scene shown, the inverse bind
// matrices are not MAT4 FLOAT (one per joint, finite), or a skinned mesh's
// JOINTS name a joint its skin does not have.
void convertSkins(const GltfContext& context, const std::vector<int>& sceneNodeOf, Scene& scene);

}  // namespace sg::scene::detail
