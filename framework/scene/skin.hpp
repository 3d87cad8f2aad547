#pragma once
// A glTF skin: the joints (nodes) whose poses move a skinned mesh's vertices.
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sg::scene {

struct Skin {
  std::string name;
  std::vector<int> joints;                     // indices into Scene::nodes; a vertex's JOINTS_n index into this
  std::vector<glm::mat4> inverseBindMatrices;  // one per joint (identity when the file gives none)
};

}  // namespace sg::scene
