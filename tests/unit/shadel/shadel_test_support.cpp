#include "shadel_test_support.hpp"

#include <algorithm>
#include <random>

namespace sg::shadel::test {

scene::Mesh meshWithUvs(std::vector<glm::vec2> uvs, std::vector<uint32_t> indices) {
  scene::Primitive primitive;
  for (glm::vec2 uv : uvs) {
    primitive.positions.emplace_back(uv, 0.0f);
    primitive.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  primitive.uv0 = std::move(uvs);
  primitive.indices = std::move(indices);
  scene::Mesh mesh;
  mesh.name = "synthetic";
  mesh.primitives.push_back(std::move(primitive));
  return mesh;
}

}  // namespace sg::shadel::test
