#include <cmath>
#include <unordered_map>

#include <shadelgraph/shadel/auto_chart.hpp>
#include <shadelgraph/shadel/chart_packing.hpp>
#include <shadelgraph/shadel/chart_parameterization.hpp>
#include <shadelgraph/shadel/chart_segmentation.hpp>

namespace sg::shadel {
namespace {

AutoChartResult failure(const scene::Mesh& mesh, std::string error) {
  AutoChartResult result;
  result.mesh = mesh;
  result.error = std::move(error);
  return result;
}

template <class T>
void copySplit(const std::vector<T>& from, std::vector<T>& to, const std::vector<uint32_t>& sourceVertex) {
  to.clear();
  if (from.empty()) return;
  to.reserve(sourceVertex.size());
  for (uint32_t v : sourceVertex) to.push_back(from[v]);
}

}  // namespace

AutoChartResult autoChartMesh(const scene::Mesh& mesh, const AutoChartOptions& options) {
  if (!(options.coneAngleDegrees > 0.0 && options.coneAngleDegrees < 90.0))
    return failure(mesh, "cone angle must be in (0, 90) degrees");
  if (options.resolution == 0 || !(options.gutterTexels >= 0.0)) return failure(mesh, "invalid resolution or gutter");
  for (size_t p = 0; p < mesh.primitives.size(); ++p)
    if (!mesh.primitives[p].uv1.empty() && !options.replaceUv1)
      return failure(mesh, "primitive " + std::to_string(p) + " already has TEXCOORD_1 (set replaceUv1 to overwrite it)");
  if (mesh.triangleCount() == 0) return failure(mesh, "the mesh has no triangles");

  AutoChartResult result;
  const FlatTriangles flat(mesh);
  const std::vector<uint32_t> grown = growCharts(flat, edgeAdjacency(mesh), options.coneAngleDegrees);
  const std::vector<ChartFrame> frames = parameterizeCharts(flat, grown, result.stats.overlapSplits);
  std::vector<glm::dvec2> sizes;
  for (const ChartFrame& frame : frames) sizes.push_back(frame.size);
  const double gutter = options.gutterTexels / options.resolution;
  const ChartPacking packing = packCharts(sizes, gutter);
  if (!packing.fits)
    return failure(mesh, std::to_string(frames.size()) + " charts with " + std::to_string(options.gutterTexels) +
                             "-texel gutters do not fit at resolution " + std::to_string(options.resolution));

  result.triangleChart.assign(flat.size(), 0);
  for (uint32_t c = 0; c < frames.size(); ++c)
    for (uint32_t t : frames[c].triangles) result.triangleChart[t] = c;

  // Split vertices per (vertex, chart) and write the chart into uv1.
  result.mesh.name = mesh.name;
  result.mesh.bounds = mesh.bounds;
  result.mesh.weights = mesh.weights;
  uint32_t meshTriangle = 0;
  for (const scene::Primitive& source : mesh.primitives) {
    scene::Primitive& out = result.mesh.primitives.emplace_back(source);
    std::unordered_map<uint64_t, uint32_t> splitVertex;  // vertex << 32 | chart -> new vertex
    std::vector<uint32_t> sourceVertex;
    std::vector<glm::vec2> uvs;
    for (size_t i = 0; i < source.indices.size(); ++i) {
      const uint32_t vertex = source.indices[i];
      const uint32_t chart = result.triangleChart[meshTriangle + i / 3];
      const auto [it, inserted] = splitVertex.try_emplace((uint64_t{vertex} << 32) | chart, static_cast<uint32_t>(sourceVertex.size()));
      if (inserted) {
        sourceVertex.push_back(vertex);
        const glm::dvec2 uv = packing.origins[chart] + frames[chart].place(glm::dvec3(source.positions[vertex])) * packing.scale;
        uvs.push_back(glm::vec2(glm::clamp(uv, glm::dvec2(0.0), glm::dvec2(1.0))));
      }
      out.indices[i] = it->second;
    }
    copySplit(source.positions, out.positions, sourceVertex);
    copySplit(source.normals, out.normals, sourceVertex);
    copySplit(source.tangents, out.tangents, sourceVertex);
    copySplit(source.uv0, out.uv0, sourceVertex);
    copySplit(source.colors, out.colors, sourceVertex);
    scene::forEachDeformationAttribute(out, [&](auto& attribute) {
      const auto from = attribute;
      copySplit(from, attribute, sourceVertex);
    });
    out.uv1 = std::move(uvs);
    out.automaticChart = true;
    result.stats.verticesIn += source.vertexCount();
    result.stats.verticesOut += out.vertexCount();
    meshTriangle += static_cast<uint32_t>(source.triangleCount());
  }

  result.stats.charts = static_cast<uint32_t>(frames.size());
  result.stats.scale = packing.scale;
  for (size_t t = 0; t < flat.size(); ++t) result.stats.zeroAreaTriangles += flat.area(t) == 0.0;
  for (const scene::Primitive& primitive : result.mesh.primitives)
    for (size_t i = 0; i + 2 < primitive.indices.size(); i += 3) {
      const glm::dvec2 a(primitive.uv1[primitive.indices[i]]), b(primitive.uv1[primitive.indices[i + 1]]),
          c(primitive.uv1[primitive.indices[i + 2]]);
      result.stats.utilisation += 0.5 * std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
    }
  return result;
}

AutoChartResult autoChartPrimitive(const scene::Primitive& primitive, const AutoChartOptions& options) {
  scene::Mesh mesh;
  mesh.primitives.push_back(primitive);
  mesh.bounds = primitive.bounds;
  return autoChartMesh(mesh, options);
}

}  // namespace sg::shadel
