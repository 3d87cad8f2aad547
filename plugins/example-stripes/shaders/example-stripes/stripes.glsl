// example-stripes: diagonal stripes over the surface's first UV set, lit
// with a Lambert term from the frame's lights plus the ambient.
// It runs in both shading paths: decoupled (one shadel per invocation) and
// forward (one pixel). It includes only the material SDK, which is embedded
// in shadelgraph (and installed, to read, under include/shadelgraph/glsl/);
// its files have include guards, so it does not matter whether the generated
// shader included them already.
#ifndef EXAMPLE_STRIPES_GLSL
#define EXAMPLE_STRIPES_GLSL

#include <framework/plugin/shaders/material.glsl>

#ifndef STRIPES_PER_UV
#define STRIPES_PER_UV 12.0
#endif

const vec3 kStripeA = vec3(0.85, 0.55, 0.10);
const vec3 kStripeB = vec3(0.08, 0.10, 0.30);

// 0..1 across a stripe pair: a square wave whose edges are smoothed over the
// footprint of one sample. The footprint comes from the Surface's UV
// derivatives (per pixel forward, per shadel decoupled), not from fwidth,
// which a compute shader does not have.
float stripeMask(Surface s) {
  float t = (s.uv0.x + s.uv0.y) * STRIPES_PER_UV;
  float footprint = (length(s.uv0Dx) + length(s.uv0Dy)) * STRIPES_PER_UV;
  float width = max(footprint, 1e-4);
  // Distance to the nearest edge of the wave (edges at t = 0.25, 0.75 mod 1),
  // signed so it is positive inside stripe A.
  float phase = fract(t);
  float d = 0.25 - abs(phase - 0.5);
  // Once a stripe pair is smaller than the footprint, fade to the average.
  float mask = clamp(0.5 + d / width, 0.0, 1.0);
  return mix(mask, 0.5, clamp(width * 2.0 - 1.0, 0.0, 1.0));
}

vec4 stripes(Surface s) {
  vec3 albedo = mix(kStripeB, kStripeA, stripeMask(s)) * s.color.rgb;
  vec3 N = s.normal;
  vec3 color = albedo * frame.ambient.rgb;
  SgLightList lights = sgLightsAt(s.position);
  for (uint k = 0u; k < lights.count; ++k) {
    LightSample light = sgLightAt(sgLight(lights, k), s.position);
    color += albedo / SG_PI * light.radiance * max(dot(N, light.direction), 0.0);
  }
  return vec4(color, 1.0);
}

#endif
