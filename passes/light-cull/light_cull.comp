#version 460
// Clustered light culling (RTR4 20.4): one thread per cluster lists, in
// ascending order, every light whose sphere of influence may touch the
// cluster (light_grid.h). The test is conservative — a sphere against the
// cluster's six planes, each pushed outwards a little so a point on a
// boundary belongs to both neighbours — so a listed subset never misses a
// light that reaches a point of the cluster: culled shading equals brute force.
#extension GL_EXT_scalar_block_layout : require
#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/light_buffer.glsl>
#include <framework/render/shaders/light_grid.h>

layout(local_size_x = 64) in;

layout(push_constant, scalar) uniform Push { SgLightCullPush cull; };

layout(set = 0, binding = kBindLightGrid, scalar) writeonly buffer Grid {
  SgLightGridHeader header;
  uint data[];
};

// Planes in world space (xyz normal, w offset; inside: dot(p.xyz, x) + p.w >= 0)
// from the rows of the view-projection (Gribb and Hartmann).
bool sphereInside(vec4 planes[6], vec3 centre, float radius) {
  for (int i = 0; i < 6; ++i)
    if (dot(planes[i].xyz, centre) + planes[i].w < -radius * length(planes[i].xyz)) return false;
  return true;
}

bool reaches(Light light, vec4 planes[6]) {
  float range = light.directionRange.w;
  // Directional lights and lights without a range reach everything.
  if (uint(light.positionType.w) == kLightDirectional || range <= 0.0) return true;
  return sphereInside(planes, light.positionType.xyz, range);
}

void main() {
  uvec4 dims = cull.grid.dims;
  uint clusters = dims.x * dims.y * dims.z;
  uint c = gl_GlobalInvocationID.x;
  if (c == 0u) header = cull.grid;
  if (c >= clusters) return;
  uint tx = c % dims.x, ty = (c / dims.x) % dims.y, slice = c / (dims.x * dims.y);
  // The cluster's extent in NDC and clip w, widened by 1/1000 of a tile and of a slice.
  vec2 tile = 2.0 / vec2(dims.xy), pad = tile * 1e-3;
  vec2 lo = vec2(tx, ty) * tile - 1.0 - pad, hi = vec2(tx + 1u, ty + 1u) * tile - 1.0 + pad;
  vec4 depth = cull.grid.depth;
  float w0 = slice == 0u ? depth.x : depth.x * exp((float(slice) - 1e-3) / depth.z);
  float w1 = slice + 1u == dims.z ? depth.y : depth.x * exp((float(slice + 1u) + 1e-3) / depth.z);
  mat4 m = transpose(frame.viewProjection);  // rows
  vec4 planes[6] = vec4[6](m[0] - lo.x * m[3], hi.x * m[3] - m[0], m[1] - lo.y * m[3], hi.y * m[3] - m[1],
                           m[3] - vec4(0.0, 0.0, 0.0, w0 * 0.999), vec4(0.0, 0.0, 0.0, w1 * 1.001) - m[3]);
  uint record = c * (dims.w + 1u), count = 0u;
  for (uint i = 0u; i < cull.lightCount; ++i) {
    if (!reaches(sgLights[i], planes)) continue;
    if (count == dims.w) {  // full: this cluster loops over every light
      count = kLightGridEveryLight;
      break;
    }
    data[record + 1u + count++] = i;
  }
  data[record] = count;
}
