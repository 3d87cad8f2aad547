#pragma once
// An automatic unique chart for meshes that have none (DamagedHelmet, Duck:
// mirrored UVs; Box: no UVs), so they can be shaded decoupled.
//
// A simple, honest method in three steps:
// 1. segmentation (chart_segmentation.hpp): grow charts over edge-adjacent
//    triangles (positions welded) whose normals lie within coneAngle of the
//    chart's seed triangle, seeds taken largest first;
// 2. parameterization (chart_parameterization.hpp): project each chart onto
//    the plane of its area-weighted normal, rotate it into its minimum-area
//    bounding rectangle, scale it by sqrt(world area / projected area) so
//    every chart gets the same texel density; a chart whose projection folds
//    over itself (checked with scene::analyzeUvSet) is cut in two through
//    its centroid, recursively, until none does;
// 3. packing (chart_packing.hpp): shelf packing of the rectangles into
//    [0,1]², tallest first, each with gutterTexels of gutter at
//    `resolution`, at the largest scale that fits (bisection).
// Vertices are split where charts meet; triangle order and every other
// attribute are kept, so triangle ids and materials do not change.
//
// The chart goes into TEXCOORD_1 (uv1): scene::chooseShadingChart prefers
// that set, and GpuScene already uploads it, so nothing downstream needs a
// new attribute. The price is that uv1 is no longer free for materials: a
// mesh that already has TEXCOORD_1 is refused unless replaceUv1 is set.
#include <cstdint>
#include <string>
#include <vector>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::shadel {

struct AutoChartOptions {
  double coneAngleDegrees = 60.0;
  uint32_t resolution = 1024;  // the level-0 size the gutter is measured at
  double gutterTexels = 4.0;   // between charts and at the border (half of it there)
  bool replaceUv1 = false;
};

struct AutoChartStats {
  uint32_t charts = 0;
  uint32_t overlapSplits = 0;  // charts cut in two because their projection folded
  double utilisation = 0.0;    // UV area of all triangles / area of [0,1]²
  double scale = 0.0;          // UV units per world unit
  uint64_t verticesIn = 0;
  uint64_t verticesOut = 0;
  uint32_t zeroAreaTriangles = 0;  // in world space: they join a neighbour's chart
};

struct AutoChartResult {
  scene::Mesh mesh;                     // a copy, with the chart in every primitive's uv1
  std::vector<uint32_t> triangleChart;  // chart of each mesh triangle (primitive by primitive)
  AutoChartStats stats;
  std::string error;  // empty on success; then `mesh` is the input, unchanged

  bool ok() const { return error.empty(); }
};

AutoChartResult autoChartMesh(const scene::Mesh& mesh, const AutoChartOptions& options = {});
// The same for one primitive (charted on its own).
AutoChartResult autoChartPrimitive(const scene::Primitive& primitive, const AutoChartOptions& options = {});

}  // namespace sg::shadel
