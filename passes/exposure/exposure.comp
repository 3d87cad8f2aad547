#version 460
// Automatic exposure: the log-average luminance of the HDR image, reduced by
// one workgroup (the image is strided over its 256 invocations).
#extension GL_EXT_scalar_block_layout : require
#include "exposure_interface.h"

layout(local_size_x = 256) in;
layout(set = 0, binding = kBindExposureHdr) uniform sampler2D hdr;
layout(set = 0, binding = kBindExposure, scalar) buffer Exposure { SgExposure result; };

shared float partial[256];

void main() {
  ivec2 size = textureSize(hdr, 0);
  uint count = uint(size.x * size.y);
  float sum = 0.0;
  for (uint i = gl_LocalInvocationIndex; i < count; i += 256u) {
    vec3 c = texelFetch(hdr, ivec2(i % uint(size.x), i / uint(size.x)), 0).rgb;
    sum += log(max(dot(c, vec3(0.2126, 0.7152, 0.0722)), 1e-4));
  }
  partial[gl_LocalInvocationIndex] = sum;
  barrier();
  for (uint s = 128u; s > 0u; s >>= 1) {
    if (gl_LocalInvocationIndex < s) partial[gl_LocalInvocationIndex] += partial[gl_LocalInvocationIndex + s];
    barrier();
  }
  if (gl_LocalInvocationIndex == 0u) {
    float logAverage = partial[0] / float(count);
    result.logAverage = logAverage;
    // Middle grey at 0.18, clamped so a dark or blown-out frame stays readable.
    result.exposure = clamp(0.18 / exp(logAverage), 0.1, 10.0);
    result.pixels = float(count);
  }
}
