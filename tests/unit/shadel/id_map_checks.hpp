#pragma once
// Independent checks of a baked triangle-ID map level, shared by the
// synthetic and the sample-model tests.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include <shadelgraph/shadel/chart_triangles.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

namespace sg::shadel::test {

struct LevelOwnership {
  uint32_t owning = 0;   // non-zero-area triangles holding >= 1 texel they touch
  uint32_t orphans = 0;  // those holding none
};

// Recomputes, from the map alone, which triangles own a texel (a texel they
// touch holds their id), and checks:
// - every texel any non-zero-area triangle touches holds an id (no holes);
// - with dilation >= 1, every 8-neighbour of such a texel does too (bilinear
//   footprints at chart edges read no empty texel);
// - every orphan is pigeonholed: no alternating path leads from it to a
//   texel whose owner holds another (else the claim step missed one), i.e.
//   the triangles it reaches touch fewer texels than they are.
LevelOwnership checkIdMapLevel(const TriangleIdMap& map, uint32_t level, const ChartTriangles& chart, bool dilated);

}  // namespace sg::shadel::test
