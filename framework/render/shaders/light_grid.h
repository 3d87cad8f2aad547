// The light grid: which lights reach each cluster of the view (clustered
// shading, RTR4 20.4), written by passes/light-cull when a frame has many
// lights and read by every light loop (lights.glsl sgLightsAt). A cluster is
// a screen tile times a slice of clip w (view depth for a perspective camera,
// slices spaced geometrically between the visible draws' nearest and
// farthest depth). Declared once for C++ (sg::shader) and GLSL.
#ifndef SG_LIGHT_GRID_H
#define SG_LIGHT_GRID_H

#include "../../gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kLightGridTilePixels = 64u;     // a tile's side on screen (more when the grid would pass 32 tiles)
SG_CONST uint kLightGridMaxTiles = 32u;       // per axis
SG_CONST uint kLightGridSlices = 16u;         // depth slices
SG_CONST uint kLightGridMaxPerCluster = 128u; // index slots per cluster; a fuller cluster uses every light
SG_CONST uint kLightGridEveryLight = 0xFFFFFFFFu;  // a cluster's count: too many to list, loop over all

// The buffer starts with the header; cluster c follows at data[c * (slots + 1)]:
// its count (or kLightGridEveryLight), then that many light indices, ascending.
struct SgLightGridHeader {
  uvec4 dims;   // x, y tiles, z slices; w = index slots per cluster (0: no grid, every light everywhere)
  vec4 depth;   // x = nearest, y = farthest clip w gridded, z = slices per natural-log unit of w / x
};

// light-cull's push constants.
struct SgLightCullPush {
  SgLightGridHeader grid;
  uint lightCount;
};

SG_SHARED_END

#endif
