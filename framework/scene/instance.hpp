#pragma once
// A placed mesh: one node of the flattened glTF hierarchy.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/object_motion.hpp>

namespace sg::scene {

// How an object is shaded. Auto lets the renderer decide (decoupled when the
// mesh has a unique UV chart and is large enough on screen).
enum class ShadingMode { Auto, Decoupled, Forward };

// "auto", "decoupled", "forward" (exact, lower case); nullopt otherwise.
std::optional<ShadingMode> parseShadingMode(std::string_view text);
std::string_view toString(ShadingMode mode);

struct Instance {
  int mesh = -1;          // index into Scene::meshes
  glm::mat4 world{1.0f};  // mesh to world, node hierarchy flattened
  std::string name;       // node name (or "node N" when unnamed)
  ShadingMode shading = ShadingMode::Auto;
  std::string material;   // its material (layer stack) by registered name; empty: the default, "gltf-pbr"
  int node = -1;          // the glTF node it hangs off (Scene::nodes), -1: none (animations do not move it)
  ObjectMotion motion;    // how it moves from `world` (its pose at time 0); none by default
  int skin = -1;          // index into Scene::skins: the glTF node's skin; -1: not skinned
  std::vector<float> morphWeights;  // current weights of its mesh's morph targets (node's, else mesh's defaults)
};

}  // namespace sg::scene
