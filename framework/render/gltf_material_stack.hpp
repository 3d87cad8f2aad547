#pragma once
// The material (layer stack) a glTF material is shaded with unless the scene
// names one: gltf-pbr, plus one layer per material extension it uses
// (registered by materials/, docs/authoring-material-layers.md section 9).
#include <string>

#include <shadelgraph/plugin/material_stack.hpp>
#include <shadelgraph/scene/material.hpp>

namespace sg::render {

// Which extension layers a stack has. The order is the physical one: the
// dielectric Fresnel (KHR_materials_ior, KHR_materials_specular) is an input
// under the base, sheen lies on the base, the clear coat on top of both.
struct GltfExtensionLayers {
  bool specular = false;  // KHR_materials_ior and/or KHR_materials_specular
  bool sheen = false;
  bool clearcoat = false;
};

// "gltf-pbr", "gltf-pbr-sheen", "gltf-pbr-specular-sheen-clearcoat", ...
inline std::string gltfMaterialStack(GltfExtensionLayers layers) {
  std::string name = plugin::kDefaultMaterial;
  if (layers.specular) name += "-specular";
  if (layers.sheen) name += "-sheen";
  if (layers.clearcoat) name += "-clearcoat";
  return name;
}

// KHR_materials_unlit wins over the lit extensions (it has no lighting to layer on).
inline GltfExtensionLayers gltfExtensionLayers(const scene::Material& material) {
  if (material.unlit) return {};
  return {.specular = material.ior.has_value() || material.specular.has_value(),
          .sheen = material.sheen.has_value(),
          .clearcoat = material.clearcoat.has_value()};
}

inline std::string gltfMaterialStack(const scene::Material& material) {
  return gltfMaterialStack(gltfExtensionLayers(material));
}

}  // namespace sg::render
