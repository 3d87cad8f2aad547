#version 460
// The farthest depth in every 16x16-pixel tile: what a draw must lie behind
// everywhere on screen to be hidden.
#extension GL_EXT_scalar_block_layout : require
#include "occlusion_interface.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindCullDepth) uniform sampler2D depth;
layout(set = 0, binding = kBindCullTiles, scalar) writeonly buffer Tiles { float tileMax[]; };
layout(push_constant, scalar) uniform Constants { SgCullConstants pc; };

void main() {
  uvec2 tile = gl_GlobalInvocationID.xy;
  if (tile.x >= pc.tilesX || tile.y >= pc.tilesY) return;
  ivec2 begin = ivec2(tile * kCullTileSize);
  ivec2 end = min(begin + ivec2(kCullTileSize), ivec2(pc.width, pc.height));
  float farthest = 0.0;
  for (int y = begin.y; y < end.y; ++y)
    for (int x = begin.x; x < end.x; ++x) farthest = max(farthest, texelFetch(depth, ivec2(x, y), 0).r);
  tileMax[tile.y * pc.tilesX + tile.x] = farthest;
}
