#version 460
// Exposure as an exposure value at ISO 100 (EV100), manual or automatic.
// Automatic: the log-average luminance of the HDR image (exposure-meter's
// per-band sums, added here in a fixed order), metered so the average lands
// on middle grey 0.18, then approached from last frame's EV100 by
// `adaptation` of the gap (a first-order filter: it cannot overshoot).
// SG_EXPOSURE_MANUAL: the manual variant, which reads no image.
// exposure = 1 / (1.2 * 2^EV100), the saturation-based sensor model (ISO 12232, S = 100).
#extension GL_EXT_scalar_block_layout : require
#include "exposure_interface.h"

layout(local_size_x = kExposureMeterBands) in;
layout(set = 0, binding = kBindExposure, scalar) buffer Exposure { SgExposure result; };
layout(push_constant, scalar) uniform Params { SgExposureParams params; };
#ifndef SG_EXPOSURE_MANUAL
layout(set = 0, binding = kBindExposureHdr) uniform sampler2D hdr;
layout(set = 0, binding = kBindExposureMeter, std430) readonly buffer Meter { float bandLogSums[]; };

shared float partial[kExposureMeterBands];
#endif

float exposureAt(float ev100) { return 1.0 / (1.2 * exp2(ev100)); }

void main() {
#ifdef SG_EXPOSURE_MANUAL
  if (gl_LocalInvocationIndex == 0u) {
    result.logAverage = 0.0;
    result.pixels = 0.0;
    result.targetEv100 = params.ev100;
    result.ev100 = params.ev100;
    result.exposure = exposureAt(params.ev100);
    result.frames = min(result.frames, 0xfffffffeu) + 1u;
  }
#else
  ivec2 size = textureSize(hdr, 0);
  uint count = uint(size.x * size.y);
  partial[gl_LocalInvocationIndex] = bandLogSums[gl_LocalInvocationIndex];
  barrier();
  for (uint s = kExposureMeterBands / 2u; s > 0u; s >>= 1) {
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
#endif
}
