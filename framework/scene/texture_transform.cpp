#include <cmath>

#include <shadelgraph/scene/material.hpp>

namespace sg::scene {

glm::mat3 TextureTransform::matrix() const {
  // The extension's reference matrices, written column by column (GLM is column-major).
  const float c = std::cos(rotation);
  const float s = std::sin(rotation);
  const glm::mat3 translation{1, 0, 0, 0, 1, 0, offset.x, offset.y, 1};
  const glm::mat3 rotationMatrix{c, s, 0, -s, c, 0, 0, 0, 1};
  const glm::mat3 scaleMatrix{scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1};
  return translation * rotationMatrix * scaleMatrix;
}

}  // namespace sg::scene
