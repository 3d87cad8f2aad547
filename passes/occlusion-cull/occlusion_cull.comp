#version 460
// Per draw: hidden when the nearest depth of its bounding sphere lies behind
// the farthest depth of every tile its screen rectangle touches. Writes this
// frame's instance count (1 visible, 0 culled) and, for draws visible now but
// not drawn into the depth yet, a command for the late depth pass.
// Conservative: anything it cannot place on screen counts as visible.
#extension GL_EXT_scalar_block_layout : require
#include "occlusion_interface.h"

layout(local_size_x = 64) in;

struct DrawCommand {
  uint indexCount;
  uint instanceCount;
  uint firstIndex;
  int vertexOffset;
  uint firstInstance;
};

layout(set = 0, binding = kBindCullTiles, scalar) readonly buffer Tiles { float tileMax[]; };
layout(set = 0, binding = kBindCullSpheres, scalar) readonly buffer Spheres { vec4 spheres[]; };
layout(set = 0, binding = kBindCullCommands, scalar) buffer Commands { DrawCommand commands[]; };
layout(set = 0, binding = kBindCullLate, scalar) writeonly buffer Late { DrawCommand late[]; };
layout(push_constant, scalar) uniform Constants { SgCullConstants pc; };

bool hidden(vec4 sphere) {
  // The cube around the sphere: its corners bound the sphere's screen
  // rectangle and nearest depth (both are extremes over a convex solid).
  vec2 lo = vec2(1e30), hi = vec2(-1e30);
  float nearest = 1e30;
  for (int i = 0; i < 8; ++i) {
    vec3 corner = sphere.xyz + sphere.w * vec3((i & 1) != 0 ? 1.0 : -1.0, (i & 2) != 0 ? 1.0 : -1.0,
                                               (i & 4) != 0 ? 1.0 : -1.0);
    vec4 clip = pc.viewProjection * vec4(corner, 1.0);
    if (clip.w <= 1e-6) return false;  // reaches behind the eye
    vec3 ndc = clip.xyz / clip.w;
    lo = min(lo, ndc.xy);
    hi = max(hi, ndc.xy);
    nearest = min(nearest, ndc.z);
  }
  if (!(nearest > 0.0 && nearest <= 1.0)) return false;  // crosses the near or far plane (or is not a number)
  if (any(isnan(lo)) || any(isnan(hi)) || any(isinf(lo)) || any(isinf(hi))) return false;
  // Pixels, with a pixel's margin; the viewport flips y.
  vec2 size = vec2(pc.width, pc.height);
  vec2 pixelLo = vec2(lo.x, -hi.y) * 0.5 * size + 0.5 * size - 1.0;
  vec2 pixelHi = vec2(hi.x, -lo.y) * 0.5 * size + 0.5 * size + 1.0;
  if (any(greaterThanEqual(pixelLo, size)) || any(lessThan(pixelHi, vec2(0.0)))) return false;  // off screen
  ivec2 tileLo = clamp(ivec2(floor(pixelLo / float(kCullTileSize))), ivec2(0), ivec2(pc.tilesX - 1, pc.tilesY - 1));
  ivec2 tileHi = clamp(ivec2(floor(pixelHi / float(kCullTileSize))), ivec2(0), ivec2(pc.tilesX - 1, pc.tilesY - 1));
  for (int y = tileLo.y; y <= tileHi.y; ++y)
    for (int x = tileLo.x; x <= tileHi.x; ++x)
      if (tileMax[y * int(pc.tilesX) + x] >= nearest) return false;
  return true;
}

void main() {
  uint d = gl_GlobalInvocationID.x;
  if (d >= pc.drawCount) return;
  bool visible = !hidden(spheres[d]);
  DrawCommand command = commands[d];
  bool drawn = command.instanceCount != 0u;
  command.instanceCount = visible && !drawn ? 1u : 0u;
  late[d] = command;
  commands[d].instanceCount = visible ? 1u : 0u;
}
