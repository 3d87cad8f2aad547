#pragma once
// The node hierarchy of the loaded glTF files, kept so that animations can
// move it: instances and cameras name the node they hang off.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace sg::scene {

struct Node {
  std::string name;  // the glTF node's, or "node N" (its index in the file)
  int parent = -1;  // index into Scene::nodes, always lower than this node's own; -1: a root
  // Local transform: translation * rotation * scale, or `matrix` when the file gives one
  // (glTF forbids animating such nodes).
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  bool hasMatrix = false;
  glm::mat4 matrix{1.0f};
  glm::mat4 placement{1.0f};  // roots only: where the scene file placed the glTF file
  std::vector<float> weights;  // morph weights at rest (node's, else its mesh's); what Weights channels animate

  glm::mat4 local() const;
};

}  // namespace sg::scene
