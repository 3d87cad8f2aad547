#pragma once
// Internal to the glTF loader: materials, and the textures and samplers they use.
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::scene::detail {

// Fills scene.materials (one per glTF material, same order), scene.textures
// (only those a material uses, decoded; see Texture for the colour-space
// split) and scene.samplers. Throws InvalidAsset, also for a used image that
// is missing or cannot be decoded.
void convertMaterials(const GltfContext& context, Scene& scene);

}  // namespace sg::scene::detail
