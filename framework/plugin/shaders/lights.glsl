// The frame's punctual lights at a surface point (KHR_lights_punctual):
// sgLightAt gives, for one of frame.lights and a world position, the unit
// direction from the position towards the light and the radiance arriving
// there (colour * intensity, times the falloff). A layer's light loop:
//   for (uint i = 0u; i < frame.counts.x; ++i) {
//     LightSample l = sgLightAt(frame.lights[i], s.position);
//     color += brdf(N, V, l.direction) * l.radiance * max(dot(N, l.direction), 0.0);
//   }
// Part of the material SDK (framework/plugin/shaders/material.glsl).
#ifndef SG_LIGHTS_GLSL
#define SG_LIGHTS_GLSL

#include <framework/render/shaders/frame.glsl>

#define SG_PI 3.14159265358979

struct LightSample {
  vec3 direction;  // world, unit: from the surface point towards the light
  vec3 radiance;   // incident radiance (no cosine term)
};

// Directional: constant, towards -direction. Point and spot: inverse square,
// windowed to 0 at the light's range when it has one (the glTF extension's
// recommended falloff); spot: times the smoothed cone factor squared.
LightSample sgLightAt(Light light, vec3 position) {
  uint type = uint(light.positionType.w);
  vec3 L;
  float attenuation = 1.0;
  if (type == SG_LIGHT_DIRECTIONAL) {
    L = -light.directionRange.xyz;
  } else {
    vec3 toLight = light.positionType.xyz - position;
    float d2 = max(dot(toLight, toLight), 1e-4);
    L = toLight * inversesqrt(d2);
    attenuation = 1.0 / d2;
    float range = light.directionRange.w;
    if (range > 0.0) attenuation *= clamp(1.0 - pow(d2 / (range * range), 2.0), 0.0, 1.0);
    if (type == SG_LIGHT_SPOT) {
      float cd = dot(light.directionRange.xyz, -L);
      float t = clamp((cd - light.cone.x) * light.cone.y, 0.0, 1.0);
      attenuation *= t * t;
    }
  }
  return LightSample(L, light.color.rgb * attenuation);
}

#endif
