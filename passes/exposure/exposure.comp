#version 460
// Exposure as an exposure value at ISO 100 (EV100), manual or automatic.
// Automatic: the log-average luminance of the HDR image, reduced by one
// workgroup (the image is strided over its 256 invocations), metered so the
// average lands on middle grey 0.18, then approached from last frame's EV100
// by `adaptation` of the gap (a first-order filter: it cannot overshoot).
// exposure = 1 / (1.2 * 2^EV100), the saturation-based sensor model (ISO 12232, S = 100).
#extension GL_EXT_scalar_block_layout : require
#include "exposure_interface.h"

layout(local_size_x = 256) in;
layout(set = 0, binding = kBindExposureHdr) uniform sampler2D hdr;
layout(set = 0, binding = kBindExposure, scalar) buffer Exposure { SgExposure result; };
layout(push_constant, scalar) uniform Params { SgExposureParams params; };

shared float partial[256];

float exposureAt(float ev100) { return 1.0 / (1.2 * exp2(ev100)); }

void main() {
  if (params.mode == kExposureManual) {  // uniform: the whole group returns
    if (gl_LocalInvocationIndex == 0u) {
      result.logAverage = 0.0;
      result.pixels = 0.0;
      result.targetEv100 = params.ev100;
      result.ev100 = params.ev100;
      result.exposure = exposureAt(params.ev100);
      result.frames = min(result.frames, 0xfffffffeu) + 1u;
    }
    return;
  }
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
    // exposureAt(ev) * average = 0.18  <=>  ev = log2(average / (0.18 * 1.2)).
    float metered = logAverage / log(2.0) - log2(0.18 * 1.2) - params.compensation;
    // A NaN average (a NaN pixel) keeps last frame's value rather than poisoning the history.
    if (isnan(metered)) metered = result.frames > 0u ? result.targetEv100 : 0.0;
    float target = clamp(metered, params.minEv100, params.maxEv100);
    float ev = result.frames > 0u && !isnan(result.ev100) ? mix(result.ev100, target, params.adaptation) : target;
    result.logAverage = logAverage;
    result.pixels = float(count);
    result.targetEv100 = target;
    result.ev100 = ev;
    result.exposure = exposureAt(ev);
    result.frames = min(result.frames, 0xfffffffeu) + 1u;
  }
}
