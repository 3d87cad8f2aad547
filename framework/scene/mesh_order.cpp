#include <shadelgraph/scene/mesh_order.hpp>

#include <vector>

#include <meshoptimizer.h>

namespace sg::scene {
namespace {

template <class T>
void remapVertices(std::vector<T>& values, const std::vector<uint32_t>& remap) {
  if (values.empty()) return;
  std::vector<T> out(values.size());
  for (size_t v = 0; v < values.size(); ++v) out[remap[v]] = values[v];
  values = std::move(out);
}

// meshopt_optimizeVertexFetchRemap's table, with the vertices no triangle
// uses (~0u) numbered after the used ones instead of dropped.
std::vector<uint32_t> firstUseRemap(const Primitive& p) {
  std::vector<uint32_t> remap(p.vertexCount());
  const size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), p.indices.data(), p.indices.size(), remap.size());
  auto next = static_cast<uint32_t>(used);
  for (uint32_t& r : remap)
    if (r == ~0u) r = next++;
  return remap;
}

}  // namespace

bool mayReorder(const Primitive& primitive, const Material& material) {
  return material.alphaMode != AlphaMode::Blend && !primitive.skinned() && !primitive.morphed() &&
         primitive.triangleCount() > 1;
}

void orderForRendering(Primitive& p, const MeshOrderOptions& options) {
  const size_t indexCount = p.indices.size() - p.indices.size() % 3;
  if (indexCount < 6) return;
  if (options.vertexCache)
    meshopt_optimizeVertexCache(p.indices.data(), p.indices.data(), indexCount, p.vertexCount());
  if (options.overdrawThreshold > 0.0f)
    meshopt_optimizeOverdraw(p.indices.data(), p.indices.data(), indexCount, &p.positions[0].x, p.vertexCount(),
                             sizeof(glm::vec3), options.overdrawThreshold);
  if (options.vertexFetch) {
    const std::vector<uint32_t> remap = firstUseRemap(p);
    for (uint32_t& index : p.indices) index = remap[index];
    remapVertices(p.positions, remap);
    remapVertices(p.normals, remap);
    remapVertices(p.tangents, remap);
    remapVertices(p.uv0, remap);
    remapVertices(p.uv1, remap);
    remapVertices(p.colors, remap);
    forEachDeformationAttribute(p, [&remap](auto& values) { remapVertices(values, remap); });
  }
}

}  // namespace sg::scene
