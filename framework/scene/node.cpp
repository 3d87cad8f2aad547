#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/node.hpp>

namespace sg::scene {

glm::mat4 Node::local() const {
  if (hasMatrix) return matrix;
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

}  // namespace sg::scene
