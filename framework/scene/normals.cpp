#include <shadelgraph/scene/normals.hpp>

namespace sg::scene {
namespace {

template <class T>
void expand(std::vector<T>& attribute, const std::vector<uint32_t>& indices) {
  if (attribute.empty()) return;
  std::vector<T> expanded;
  expanded.reserve(indices.size());
  for (uint32_t index : indices) expanded.push_back(attribute[index]);
  attribute = std::move(expanded);
}

}  // namespace

void deindex(Primitive& primitive) {
  expand(primitive.positions, primitive.indices);
  expand(primitive.normals, primitive.indices);
  expand(primitive.tangents, primitive.indices);
  expand(primitive.uv0, primitive.indices);
  expand(primitive.uv1, primitive.indices);
  expand(primitive.colors, primitive.indices);
  forEachDeformationAttribute(primitive, [&](auto& attribute) { expand(attribute, primitive.indices); });
  for (size_t i = 0; i < primitive.indices.size(); ++i) primitive.indices[i] = static_cast<uint32_t>(i);
}

void generateFlatNormals(Primitive& primitive) {
  deindex(primitive);
  const std::vector<glm::vec3>& p = primitive.positions;
  primitive.normals.assign(p.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  for (size_t corner = 0; corner + 2 < p.size(); corner += 3) {
    const glm::vec3 cross = glm::cross(p[corner + 1] - p[corner], p[corner + 2] - p[corner]);
    const float length = glm::length(cross);
    if (!(length > 0.0f)) continue;
    const glm::vec3 normal = cross / length;
    for (size_t k = 0; k < 3; ++k) primitive.normals[corner + k] = normal;
  }
}

}  // namespace sg::scene
