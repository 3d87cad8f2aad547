#version 460
// Bloom: the light above white (exposed luminance over 1, where tonemap
// saturates) spread by a downsample / upsample pyramid (each level a 2x2 box
// of the one above, then each added to the finer one bilinearly), added to
// the HDR colour before tonemap. One step per dispatch (bloom_interface.h).
#extension GL_EXT_scalar_block_layout : require
#include "bloom_interface.h"
#include "../exposure/exposure_interface.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindBloomHdr) uniform sampler2D hdr;
layout(set = 0, binding = kBindBloomExposure, scalar) readonly buffer Exposure { SgExposure exposure; };
layout(set = 0, binding = kBindBloomSource, rgba16f) uniform readonly image2D source;
layout(set = 0, binding = kBindBloomTarget, rgba16f) uniform image2D target;
layout(push_constant, scalar) uniform Push { SgBloomPush p; };

// Finite, non-negative, within half-float range: what every step stores.
vec3 bounded(vec3 c) {
  c = clamp(c, vec3(0.0), vec3(65000.0));
  return any(isnan(c)) ? vec3(0.0) : c;
}

vec3 hdrAt(ivec2 q) { return bounded(texelFetch(hdr, clamp(q, ivec2(0), textureSize(hdr, 0) - 1), 0).rgb); }

// The part of a colour above white once exposed, in the colour's own (unexposed) units.
vec3 bright(vec3 c) {
  float e = exposure.exposure;
  float l = dot(c, vec3(0.2126, 0.7152, 0.0722)) * e;
  return (isnan(e) || l <= 1.0) ? vec3(0.0) : c * ((l - 1.0) / l);
}

vec3 sourceBilinear(vec2 at) {
  ivec2 size = imageSize(source);
  vec2 t = at - 0.5;
  ivec2 b = ivec2(floor(t));
  vec2 f = t - vec2(b);
  vec3 c = vec3(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      c += (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) *
           imageLoad(source, clamp(b + ivec2(i, j), ivec2(0), size - 1)).rgb;
  return c;
}

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(at, imageSize(target)))) return;
  vec3 c;
  if (p.step == kBloomStepBright) {
    c = 0.25 * (bright(hdrAt(2 * at)) + bright(hdrAt(2 * at + ivec2(1, 0))) + bright(hdrAt(2 * at + ivec2(0, 1))) +
                bright(hdrAt(2 * at + ivec2(1, 1))));
  } else if (p.step == kBloomStepDown) {
    ivec2 last = imageSize(source) - 1;
    c = 0.25 * (imageLoad(source, min(2 * at, last)).rgb + imageLoad(source, min(2 * at + ivec2(1, 0), last)).rgb +
                imageLoad(source, min(2 * at + ivec2(0, 1), last)).rgb + imageLoad(source, min(2 * at + ivec2(1, 1), last)).rgb);
  } else if (p.step == kBloomStepUp) {
    // This texel's centre in the coarser level's texels.
    c = imageLoad(target, at).rgb + sourceBilinear((vec2(at) + 0.5) * vec2(imageSize(source)) / vec2(imageSize(target)));
  } else {
    c = hdrAt(at) + p.strength / float(p.levels) *
                        sourceBilinear((vec2(at) + 0.5) * vec2(imageSize(source)) / vec2(imageSize(target)));
  }
  imageStore(target, at, vec4(bounded(c), 1.0));
}
