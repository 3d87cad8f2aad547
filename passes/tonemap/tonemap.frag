#version 460
// HDR -> display: exposure from the exposure pass, ACES filmic fit (Narkowicz
// 2015); the sRGB output format applies the transfer function.
#extension GL_EXT_scalar_block_layout : require
#include <passes/exposure/exposure_interface.h>

layout(set = 0, binding = kBindExposureHdr) uniform sampler2D hdr;
layout(set = 0, binding = kBindExposure, scalar) readonly buffer Exposure { SgExposure result; };
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

vec3 acesFilm(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
#ifdef SG_TONEMAP_PASSTHROUGH
  // Debug views: their colours go to the display unchanged.
  outColor = vec4(texture(hdr, inUv).rgb, 1.0);
#else
  vec3 c = texture(hdr, inUv).rgb * result.exposure;
  outColor = vec4(acesFilm(c), 1.0);
#endif
}
