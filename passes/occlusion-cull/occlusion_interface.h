// The occlusion-cull passes' bindings and push constants, declared once for
// C++ (sg::shader) and GLSL.
#ifndef SG_OCCLUSION_INTERFACE_H
#define SG_OCCLUSION_INTERFACE_H

#include "../../framework/gpu/shaders/shared.h"

SG_SHARED_BEGIN

SG_CONST uint kCullTileSize = 16u;    // pixels per side of a tile of the max-depth grid
SG_CONST uint kBindCullDepth = 0u;    // hi-z: the depth of the draws visible last frame (sampled)
SG_CONST uint kBindCullTiles = 1u;    // float per tile: the farthest depth in it
SG_CONST uint kBindCullSpheres = 2u;  // vec4 per draw: world bounding sphere (xyz centre, w radius)
SG_CONST uint kBindCullCommands = 3u; // VkDrawIndexedIndirectCommand per draw: in, last frame's; out, this frame's
SG_CONST uint kBindCullLate = 4u;     // VkDrawIndexedIndirectCommand per draw: visible now, not drawn yet

struct SgCullConstants {
  mat4 viewProjection;  // world to clip (depth 0..1, +y up: the viewport flips it)
  uint drawCount;
  uint width;
  uint height;
  uint tilesX;
  uint tilesY;
};

SG_SHARED_END

#endif
