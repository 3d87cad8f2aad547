#pragma once
// Triangle-ID maps (paper §3.2, after Hillesland & Yang 2016): per detail
// level, the mesh triangle each shadel of the chart belongs to, so
// layer-shade can interpolate the triangle's vertex attributes as a
// fragment shader would. An asset-cooking step, done on the CPU (lavapipe has
// no conservative rasterization) and cached on disk (id_map_cache.hpp).
//
// Per level, texel (x, y) covers UV [x, x+1] / size x [y, y+1] / size (rows
// top to bottom, v down, like the shading UVs), and holds, in order of
// precedence:
// 1. normal coverage: the triangle covering the texel's centre, top-left rule
//    on shared edges (what a GPU rasterizer would write);
// 2. conservative coverage where (1) left nothing: of the triangles with
//    area in the texel, the one nearest its centre (the smallest
//    extrapolation by layer-shade's clamped barycentrics). A triangle too
//    small to have area in any texel at this level counts as touching the
//    texel under its centroid. After (1) and (2) no texel that any triangle
//    touches is empty: every UV point of the chart has an ID;
// 3. claims: (1) and (2) can leave a triangle owning no texel (a tiny or
//    sliver triangle whose texels neighbours' centres cover). Each such
//    orphan takes one texel it touches from a triangle that owns two or
//    more, preferring texels from (2) over (1), then the one nearest its UV
//    centroid, along augmenting paths (A takes B's only texel while B takes
//    one from C...) as in bipartite matching. So an orphan remains only when
//    none can be had: when a set of triangles touches fewer texels than it
//    has members, as at coarse levels where thousands of triangles share 64
//    texels. Those are counted (orphanTriangles);
// 4. dilation: `dilation` rings of empty texels around the chart take the
//    ID of the nearest triangle among their 8 neighbours, so a bilinear
//    footprint at the chart's edge never reads an empty texel.
// Triangles of zero UV area (<= kZeroUvArea) take part in none of this: they
// have no interior, and layer-shade could not compute barycentrics for them.
// Pixels of such a triangle take their shading from the texels under its UVs,
// i.e. from its neighbours (extrapolated by clamped barycentrics); those
// texels are non-empty unless the triangle lies away from every other
// triangle, which is counted (zeroAreaUncovered). Everything else holds
// kNoTriangle.
#include <cstdint>
#include <span>
#include <vector>

#include <shadelgraph/scene/mesh.hpp>
#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/detail_levels.hpp>

namespace sg::shadel {

inline constexpr uint32_t kNoTriangle = 0xFFFFFFFFu;

struct IdMapOptions {
  uint32_t level0Size = 1024;  // power of two; see chooseLevel0Size
  uint32_t minLevelSize = kDefaultMinLevelSize;
  uint32_t dilation = 1;  // rings; 1 is what a bilinear footprint needs
  bool claimOrphans = true;

  bool operator==(const IdMapOptions&) const = default;
};

struct IdMapLevelStats {
  uint32_t size = 0;
  uint64_t normalTexels = 0;        // (1)
  uint64_t conservativeTexels = 0;  // (2)
  uint64_t claimedTexels = 0;       // (3)
  uint64_t dilatedTexels = 0;       // (4)
  uint64_t emptyTexels = 0;
  uint32_t owningTriangles = 0;    // non-zero-area triangles owning a texel through (1)-(3)
  uint32_t orphanTriangles = 0;    // non-zero-area triangles owning none
  uint32_t zeroAreaUncovered = 0;  // zero-area triangles whose UV centroid's texel is empty

  bool operator==(const IdMapLevelStats&) const = default;
};

// GPU upload: `texels` as is; level l of size levelSize(l) starts at
// levelOffsets[l] = sum of the finer levels' size², rows of levelSize(l).
struct TriangleIdMap {
  DetailLevels levels;
  uint32_t triangleCount = 0;
  uint32_t zeroAreaTriangles = 0;
  std::vector<uint32_t> primitiveTriangleBase;  // triangle id of each primitive's first triangle
  std::vector<uint64_t> levelOffsets;           // where each level starts in texels
  std::vector<uint32_t> texels;                 // all levels, finest first
  std::vector<IdMapLevelStats> stats;           // per level

  std::span<const uint32_t> level(uint32_t l) const {
    return std::span<const uint32_t>(texels).subspan(levelOffsets[l], uint64_t{levels.levelSize(l)} * levels.levelSize(l));
  }
  uint32_t at(uint32_t l, uint32_t x, uint32_t y) const {
    return texels[levelOffsets[l] + uint64_t{y} * levels.levelSize(l) + x];
  }
};

// Bakes every level of the mesh in the chart's UV set (shifted by its
// tileOffset). Throws std::invalid_argument when the chart has no UV set or
// the options give no valid level chain.
TriangleIdMap bakeTriangleIdMap(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const IdMapOptions& options);

}  // namespace sg::shadel
