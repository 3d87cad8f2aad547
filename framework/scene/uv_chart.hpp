#pragma once
// Shading-UV analysis: can a UV set serve as the unique chart that decoupled
// shading needs (every surface point its own spot in shadel space)?
//
// A set qualifies when
// - all its UVs lie in one unit tile [i, i+1] x [j, j+1] (within
//   rangeEpsilon): usually [0,1]², but DamagedHelmet's chart sits in
//   [0,1] x [1,2], which is as good once shifted by tileOffset;
// - no two triangles overlap: their interiors intersect with an area above
//   overlapAreaEpsilon (sharing an edge or a vertex is fine). Candidate pairs
//   come from a uniform grid over the chart, so this is near-linear in the
//   triangle count; each pair gets an exact separating-axis test, then the
//   area of the intersection polygon;
// - at most maxZeroAreaFraction of its triangles have zero UV area (area <=
//   zeroAreaEpsilon): a few are harmless (DamagedHelmet has 10), a set of all
//   zeros is no chart. They are skipped by the overlap test.
// Triangles of zero surface area (3D area <= zeroSurfaceAreaEpsilon times the
// squared diagonal of the primitive's bounds) cover no pixel and are left out
// of every check and count but degenerateTriangles (CAD meshes, e.g.
// 2CylinderEngine, have many). Not for skinned or morphed primitives, whose
// triangles may open up when posed.
#include <cstddef>
#include <string>

#include <glm/glm.hpp>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::scene {

struct UvChartOptions {
  double rangeEpsilon = 1e-4;
  double zeroAreaEpsilon = 1e-10;     // in UV units²: ~1/400 of a texel at 8K²
  double overlapAreaEpsilon = 1e-10;  // in UV units²
  double maxZeroAreaFraction = 0.01;
  double zeroSurfaceAreaEpsilon = 1e-12;  // relative to the squared diagonal of the bounds
  // Counting stops here: a chart this broken needs no exact numbers, and
  // fully stacked UVs would otherwise cost O(n²).
  size_t maxOverlappingPairs = 1'000'000;
};

struct ChartVerdict {
  int uvSet = -1;               // the set the counts describe (0 or 1); -1: there are no UVs
  bool unique = false;          // uvSet is usable as the shading chart
  glm::vec2 tileOffset{0.0f};   // integral; shading UV = uv - tileOffset lies in [0,1]²
  size_t triangles = 0;             // not counting degenerate ones
  size_t degenerateTriangles = 0;   // zero surface area: ignored
  size_t overlappingPairs = 0;      // pairs of triangles whose interiors overlap
  size_t overlappingTriangles = 0;  // triangles in at least one such pair
  size_t outOfRangeUvs = 0;         // vertices outside the tile
  size_t zeroAreaTriangles = 0;
  bool countsTruncated = false;  // maxOverlappingPairs was reached: overlap counts are lower bounds
  std::string reason;            // one line for people, e.g. "TEXCOORD_0: 2620 overlapping triangle pairs"
};

// Analyzes one UV set (0 or 1) of a primitive, or of all primitives of a mesh
// together (an instance gets one region of shadel space for all of them).
ChartVerdict analyzeUvSet(const Primitive& primitive, int uvSet, const UvChartOptions& options = {});
ChartVerdict analyzeUvSet(const Mesh& mesh, int uvSet, const UvChartOptions& options = {});

// TEXCOORD_1 if it qualifies, else TEXCOORD_0 (lightmap-style second sets are
// the usual unique charts). When neither does, the verdict describes the last
// set examined and `reason` says what is wrong with each.
ChartVerdict chooseShadingChart(const Primitive& primitive, const UvChartOptions& options = {});
ChartVerdict chooseShadingChart(const Mesh& mesh, const UvChartOptions& options = {});

}  // namespace sg::scene
