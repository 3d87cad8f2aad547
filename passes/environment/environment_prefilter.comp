#version 460
// The environment light's one-time prefilter (Karis 2013, "Real Shading in
// Unreal Engine 4"): the equirectangular HDR image box-filtered to specular
// level 0, the cosine-convolved irradiance (E / pi), the GGX-prefiltered
// specular levels (N = V = R, filtered importance sampling) and the split-sum BRDF lookup of brdf.glsl's
// GGX with height-correlated Smith visibility. One step per dispatch.
#extension GL_EXT_scalar_block_layout : require
#include "environment_interface.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = kBindEnvSource, scalar) readonly buffer Source { vec4 texels[]; };
layout(set = 0, binding = kBindEnvSpecularOut, rgba32f) uniform image2D specular;
layout(set = 0, binding = kBindEnvIrradianceOut, rgba32f) uniform writeonly image2D irradiance;
layout(set = 0, binding = kBindEnvBrdfOut, rgba32f) uniform writeonly image2D brdf;
layout(push_constant, scalar) uniform Push { SgEnvironmentPush p; };

const float kPi = 3.14159265358979;
const ivec2 kLevel = ivec2(kEnvSpecularWidth, kEnvSpecularWidth / 2u);

// The direction through equirectangular coordinates uv (environment.glsl's sgEquirectUv inverted).
vec3 directionAt(vec2 uv) {
  float theta = uv.y * kPi, phi = (uv.x - 0.5) * 2.0 * kPi;
  return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}

vec2 uvOf(vec3 d) { return vec2(atan(d.x, -d.z) / (2.0 * kPi) + 0.5, acos(clamp(d.y, -1.0, 1.0)) / kPi); }

// Level 0 (k = 0) or its halving k: size and where its texels start in `specular`.
ivec2 mipSize(int k) { return ivec2(kLevel.x >> k, kLevel.y >> k); }
ivec2 mipOrigin(int k) { return k == 0 ? ivec2(0) : ivec2(kLevel.x - ((2 * kLevel.x) >> k), kLevel.y * int(kEnvSpecularLevels)); }

// Bilinear read of level 0's mip k: u wraps, v clamps.
vec3 mipRead(vec3 d, int k) {
  ivec2 size = mipSize(k), origin = mipOrigin(k);
  vec2 t = uvOf(d) * vec2(size) - 0.5;
  ivec2 b = ivec2(floor(t));
  vec2 f = t - vec2(b);
  vec3 c = vec3(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 q = ivec2(((b.x + i) % size.x + size.x) % size.x, clamp(b.y + j, 0, size.y - 1));
      c += (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y) * imageLoad(specular, origin + q).rgb;
    }
  return c;
}

// Level 0 filtered to mip `lod` (trilinear between its halvings).
vec3 level0(vec3 d, float lod) {
  lod = clamp(lod, 0.0, float(kEnvPyramidMips));
  int a = int(floor(lod)), b = min(a + 1, int(kEnvPyramidMips));
  vec3 ca = mipRead(d, a);
  return lod > float(a) ? mix(ca, mipRead(d, b), lod - float(a)) : ca;
}

vec2 hammersley(uint i, uint n) { return vec2(float(i) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10); }

// A GGX half vector around N for sample xi (alpha = roughness^2).
vec3 ggxHalf(vec2 xi, vec3 N, float alpha) {
  float phi = 2.0 * kPi * xi.x;
  float cosTheta = sqrt((1.0 - xi.y) / (1.0 + (alpha * alpha - 1.0) * xi.y));
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  vec3 h = vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
  vec3 up = abs(N.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(up, N)), b = cross(N, t);
  return normalize(t * h.x + b * h.y + N * h.z);
}

float ggxD(float NdotH, float alpha) {
  float a2 = alpha * alpha, k = NdotH * NdotH * (a2 - 1.0) + 1.0;
  return a2 / (kPi * k * k);
}

float visibilitySmithGgx(float NdotL, float NdotV, float alpha) {
  float a2 = alpha * alpha;
  float g = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2) + NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
  return g > 0.0 ? 0.5 / g : 0.0;
}

// Finite and within half-float range wherever these values end up (RGBA16F colour targets).
vec3 bounded(vec3 c) { return clamp(c, vec3(0.0), vec3(65000.0)); }

void main() {
  ivec2 at = ivec2(gl_GlobalInvocationID.xy);
  if (p.step == kEnvStepDownsample) {
    ivec2 size = mipSize(int(p.level));
    if (any(greaterThanEqual(at, size))) return;
    // The source texels under this texel, at most 16 x 16 of them (strided beyond).
    uvec2 src = uvec2(p.sourceWidth, p.sourceHeight);
    uvec2 lo = uvec2(at) * src / uvec2(size), hi = max(lo + 1u, (uvec2(at) + 1u) * src / uvec2(size));
    uvec2 stride = max((hi - lo) / 16u, uvec2(1u));
    vec3 sum = vec3(0.0);
    float n = 0.0;
    for (uint y = lo.y; y < hi.y; y += stride.y)
      for (uint x = lo.x; x < hi.x; x += stride.x) {
        sum += texels[y * src.x + x].rgb;
        n += 1.0;
      }
    imageStore(specular, mipOrigin(int(p.level)) + at, vec4(bounded(sum / n), 1.0));
  } else if (p.step == kEnvStepBrdf) {
    if (any(greaterThanEqual(at, ivec2(kEnvBrdfSize)))) return;
    float NdotV = max(float(at.x) / float(kEnvBrdfSize - 1u), 1e-4);
    float roughness = float(at.y) / float(kEnvBrdfSize - 1u);
    float alpha = max(roughness * roughness, 1e-3);
    vec3 V = vec3(sqrt(1.0 - NdotV * NdotV), 0.0, NdotV), N = vec3(0.0, 0.0, 1.0);
    vec2 ab = vec2(0.0);
    for (uint i = 0u; i < kEnvBrdfSamples; ++i) {
      vec3 H = ggxHalf(hammersley(i, kEnvBrdfSamples), N, alpha);
      vec3 L = reflect(-V, H);
      float NdotL = clamp(L.z, 0.0, 1.0), NdotH = clamp(H.z, 0.0, 1.0), VdotH = clamp(dot(V, H), 0.0, 1.0);
      if (NdotL <= 0.0) continue;
      // f * NdotL / pdf with pdf = D * NdotH / (4 VdotH): the D cancels.
      float g = visibilitySmithGgx(NdotL, NdotV, alpha) * NdotL * 4.0 * VdotH / max(NdotH, 1e-6);
      float fc = pow(1.0 - VdotH, 5.0);
      ab += vec2((1.0 - fc) * g, fc * g);
    }
    imageStore(brdf, at, vec4(ab / float(kEnvBrdfSamples), 0.0, 1.0));
  } else if (p.step == kEnvStepIrradiance) {
    ivec2 size = ivec2(kEnvIrradianceWidth, kEnvIrradianceWidth / 2u);
    if (any(greaterThanEqual(at, size))) return;
    vec3 N = directionAt((vec2(at) + 0.5) / vec2(size));
    // Every texel of level 0 weighted by its solid angle and the cosine: E / pi.
    vec3 sum = vec3(0.0);
    float texelAngle = (2.0 * kPi / float(kLevel.x)) * (kPi / float(kLevel.y));
    for (int y = 0; y < kLevel.y; ++y) {
      float sinTheta = sin((float(y) + 0.5) / float(kLevel.y) * kPi);
      for (int x = 0; x < kLevel.x; ++x) {
        vec3 d = directionAt((vec2(x, y) + 0.5) / vec2(kLevel));
        float c = dot(N, d);
        if (c > 0.0) sum += imageLoad(specular, ivec2(x, y)).rgb * (c * sinTheta * texelAngle);
      }
    }
    imageStore(irradiance, at, vec4(bounded(sum / kPi), 1.0));
  } else {
    if (any(greaterThanEqual(at, kLevel))) return;
    float roughness = float(p.level) / float(kEnvSpecularLevels - 1u);
    float alpha = max(roughness * roughness, 1e-3);
    vec3 N = directionAt((vec2(at) + 0.5) / vec2(kLevel));
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    // Filtered importance sampling (Colbert & Krivanek, GPU Gems 3 ch. 20): each sample
    // reads the mip whose texels cover its share of the lobe, 1 / (n pdf) steradians, so
    // few samples of a wide lobe do not alias the bright texels they land on into streaks.
    float texelAngle = (2.0 * kPi / float(kLevel.x)) * (kPi / float(kLevel.y));  // times sin(theta)
    for (uint i = 0u; i < kEnvSpecularSamples; ++i) {
      vec3 H = ggxHalf(hammersley(i, kEnvSpecularSamples), N, alpha);
      vec3 L = reflect(-N, H);
      float NdotL = dot(N, L);
      if (NdotL <= 0.0) continue;
      float pdf = ggxD(clamp(dot(N, H), 0.0, 1.0), alpha) * 0.25;  // D NdotH / (4 VdotH), N = V
      float sampleAngle = 1.0 / (float(kEnvSpecularSamples) * max(pdf, 1e-6));
      float pixelAngle = texelAngle * max(sqrt(max(1.0 - L.y * L.y, 0.0)), 1.0 / float(kLevel.y));
      float lod = 0.5 * log2(sampleAngle / pixelAngle) + 1.0;  // +1: neighbouring samples' footprints overlap
      sum += level0(L, lod) * NdotL;
      weight += NdotL;
    }
    imageStore(specular, at + ivec2(0, int(p.level) * kLevel.y), vec4(bounded(sum / max(weight, 1e-6)), 1.0));
  }
}
