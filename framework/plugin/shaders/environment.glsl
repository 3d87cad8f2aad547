// The scene's environment light, prefiltered once (passes/environment): when
// frame.environment.x > 0, the scene named an equirectangular HDR image and
//   sgEnvironmentDiffuse(N)             the cosine-weighted radiance around N (irradiance / pi),
//   sgEnvironmentSpecular(R, roughness) the GGX-prefiltered radiance along R,
//   sgEnvironmentBrdf(NdotV, roughness) the split-sum scale and bias (f0 * x + y)
// give image-based lighting; otherwise the maps are 1x1 stand-ins and a
// material keeps its analytic sky. Radiance in cd/m^2 (the image times its intensity).
// Part of the material SDK (framework/plugin/shaders/material.glsl).
#ifndef SG_ENVIRONMENT_GLSL
#define SG_ENVIRONMENT_GLSL

#include <framework/render/shaders/frame.glsl>

layout(set = 0, binding = kBindEnvironmentIrradiance) uniform sampler2D sgEnvIrradiance;
layout(set = 0, binding = kBindEnvironmentSpecular) uniform sampler2D sgEnvSpecular;
layout(set = 0, binding = kBindEnvironmentBrdf) uniform sampler2D sgEnvBrdf;

// Equirectangular coordinates of a direction: u = atan2(x, -z) / 2pi + 1/2, v = acos(y) / pi (0 straight up).
vec2 sgEquirectUv(vec3 d) {
  d = normalize(d);
  return vec2(atan(d.x, -d.z) * (0.5 / 3.14159265358979) + 0.5, acos(clamp(d.y, -1.0, 1.0)) * (1.0 / 3.14159265358979));
}

// Bilinear read of a `size` map whose rows start at `row` in `map`: u wraps, v clamps.
// (Fetched texel by texel: the maps are RGBA32F, which need not be filterable.)
vec3 sgEquirectRead(sampler2D map, vec2 uv, ivec2 size, int row) {
  vec2 t = uv * vec2(size) - 0.5;
  ivec2 b = ivec2(floor(t));
  vec2 f = t - vec2(b);
  vec3 c = vec3(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      int x = ((b.x + i) % size.x + size.x) % size.x;
      int y = clamp(b.y + j, 0, size.y - 1);
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      c += w * texelFetch(map, ivec2(x, row + y), 0).rgb;
    }
  return c;
}

vec3 sgEnvironmentDiffuse(vec3 N) {
  ivec2 size = textureSize(sgEnvIrradiance, 0);
  return sgEquirectRead(sgEnvIrradiance, sgEquirectUv(N), size, 0) * frame.environment.y;
}

// Levels of width w and height w/2 stacked top to bottom, roughness 0 first, evenly spaced to 1.
vec3 sgEnvironmentSpecular(vec3 R, float roughness) {
  ivec2 full = textureSize(sgEnvSpecular, 0);
  ivec2 size = ivec2(full.x, max(full.x / 2, 1));
  int levels = max(full.y / size.y, 1);
  float lod = clamp(roughness, 0.0, 1.0) * float(levels - 1);
  int l0 = int(floor(lod)), l1 = min(l0 + 1, levels - 1);
  vec2 uv = sgEquirectUv(R);
  vec3 a = sgEquirectRead(sgEnvSpecular, uv, size, l0 * size.y), b = sgEquirectRead(sgEnvSpecular, uv, size, l1 * size.y);
  return mix(a, b, lod - float(l0)) * frame.environment.y;
}

vec2 sgEnvironmentBrdf(float NdotV, float roughness) {
  ivec2 size = textureSize(sgEnvBrdf, 0);
  vec2 t = clamp(vec2(NdotV, roughness), 0.0, 1.0) * vec2(size - 1);
  ivec2 b = min(ivec2(floor(t)), size - 2);
  vec2 f = t - vec2(b);
  if (size.x < 2 || size.y < 2) return vec2(1.0, 0.0);  // the stand-in
  vec2 c00 = texelFetch(sgEnvBrdf, b, 0).rg, c10 = texelFetch(sgEnvBrdf, b + ivec2(1, 0), 0).rg;
  vec2 c01 = texelFetch(sgEnvBrdf, b + ivec2(0, 1), 0).rg, c11 = texelFetch(sgEnvBrdf, b + ivec2(1, 1), 0).rg;
  return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
}

#endif
