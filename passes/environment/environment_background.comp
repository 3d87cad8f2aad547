#version 460
// The environment behind everything: a pixel whose depth is at the far plane
// (nothing drawn there) takes the image's radiance times its intensity in the
// direction through the pixel; drawn pixels keep their colour. Before
// exposure, so the background is metered and tonemapped like the scene.
#extension GL_EXT_scalar_block_layout : require
#include "environment_interface.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindEnvBackgroundSource, scalar) readonly buffer Source { vec4 texels[]; };
layout(set = 0, binding = kBindEnvBackgroundDepth) uniform sampler2D depth;
layout(set = 0, binding = kBindEnvBackgroundHdr, rgba16f) uniform image2D hdr;
layout(push_constant, scalar) uniform Push { SgEnvironmentBackgroundPush p; };

const float kPi = 3.14159265358979;

// environment.glsl's sgEquirectUv.
vec2 uvOf(vec3 d) { return vec2(atan(d.x, -d.z) / (2.0 * kPi) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / kPi); }

// Bilinear read of the image: u wraps, v clamps.
vec3 radiance(vec3 d) {
  ivec2 size = ivec2(p.sourceSize);
  vec2 t = uvOf(d) * vec2(size) - 0.5;
  ivec2 b = ivec2(floor(t));
  vec2 f = t - vec2(b);
  vec3 c = vec3(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      int x = ((b.x + i) % size.x + size.x) % size.x, y = clamp(b.y + j, 0, size.y - 1);
      c += (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) * texels[y * size.x + x].rgb;
    }
  return c;
}

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(at, ivec2(p.targetSize)))) return;
  if (texelFetch(depth, at, 0).r < 1.0) return;
  // Scene passes flip the viewport: row 0 is clip y = +1.
  vec2 ndc = vec2((float(at.x) + 0.5) / float(p.targetSize.x) * 2.0 - 1.0,
                  1.0 - (float(at.y) + 0.5) / float(p.targetSize.y) * 2.0);
  vec4 near = p.clipToWorld * vec4(ndc, 0.0, 1.0), far = p.clipToWorld * vec4(ndc, 1.0, 1.0);
  // far - near, scaled by near.w * far.w (both >= 0): finite for an infinite far plane too (far.w = 0).
  vec3 d = normalize(far.xyz * near.w - near.xyz * far.w);
  // Within half-float range (the RGBA16F target), like the prefiltered maps.
  vec3 c = clamp(radiance(d) * p.intensity, vec3(0.0), vec3(65000.0));
  imageStore(hdr, at, vec4(c, 1.0));
}
