#version 460
// The first half of automatic exposure: workgroup b sums the natural log of
// the luminance of band b of the image's rows (kExposureMeterBands bands).
// exposure.comp adds the bands in a fixed order, so the result does not
// depend on which workgroup finishes first.
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "exposure_interface.h"

layout(local_size_x = 64) in;
layout(set = 0, binding = kBindExposureHdr) uniform sampler2D hdr;
layout(set = 0, binding = kBindExposureMeter, std430) writeonly buffer Meter { float bandLogSums[]; };

shared float partial[64];  // one per subgroup (at least 1 lane each)

void main() {
  ivec2 size = textureSize(hdr, 0);
  uint band = gl_WorkGroupID.x;
  uint firstRow = uint(size.y) * band / kExposureMeterBands;
  uint endRow = uint(size.y) * (band + 1u) / kExposureMeterBands;
  float sum = 0.0;
  // Row by row, no division per pixel (integer division is slow on SIMD CPUs).
  for (uint y = firstRow; y < endRow; ++y) {
    for (uint x = gl_LocalInvocationIndex; x < uint(size.x); x += 64u) {
      vec3 c = texelFetch(hdr, ivec2(x, y), 0).rgb;
      sum += log(max(dot(c, vec3(0.2126, 0.7152, 0.0722)), 1e-4));
    }
  }
  // A subgroup sum, then one barrier: llvmpipe runs every barrier as a switch
  // of each subgroup's coroutine, so a shared-memory tree costs more than the
  // pixels of a small band.
  sum = subgroupAdd(sum);
  if (subgroupElect()) partial[gl_SubgroupID] = sum;
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    float total = 0.0;
    for (uint i = 0u; i < gl_NumSubgroups; ++i) total += partial[i];
    bandLogSums[band] = total;
  }
}
