#pragma once
// A material: an ordered stack of layers. Each layer may read the ones
// before it; the last one's vec4 is what the object shows (radiance, alpha).
#include <string>
#include <vector>

namespace sg::plugin {

struct MaterialStack {
  std::string name;                 // e.g. "gltf-pbr", the default of every object
  std::vector<std::string> layers;  // layer names, in order
  // The material objects use when shaded forward, required when a layer is
  // DecoupledOnly (empty: this stack itself).
  std::string forwardFallback;
  std::string plugin;  // who registered it (set by the registry)
};

inline constexpr const char* kDefaultMaterial = "gltf-pbr";

}  // namespace sg::plugin
