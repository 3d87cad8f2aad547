// The frame's punctual lights at a surface point (KHR_lights_punctual):
// sgLightsAt gives the lights that may reach a world position (every light,
// or its cluster's list when the frame has a light grid: passes/light-cull),
// sgLight the k-th of them, and sgLightAt, for one light and the position, the
// unit direction from the position towards the light and the radiance arriving
// there (colour * intensity, times the falloff, times the light's shadow
// visibility when it has a shadow map). A layer's light loop:
//   SgLightList lights = sgLightsAt(s.position);
//   for (uint k = 0u; k < lights.count; ++k) {
//     LightSample l = sgLightAt(sgLight(lights, k), s.position);
//     color += brdf(N, V, l.direction) * l.radiance * max(dot(N, l.direction), 0.0);
//   }
// Part of the material SDK (framework/plugin/shaders/material.glsl).
#ifndef SG_LIGHTS_GLSL
#define SG_LIGHTS_GLSL

#include <framework/render/shaders/frame.glsl>
#include <framework/render/shaders/light_buffer.glsl>
#include <framework/render/shaders/light_grid.h>

#define SG_PI 3.14159265358979

// The light grid (light_grid.h), or a stand-in whose header says "no grid".
layout(set = 0, binding = kBindLightGrid, scalar) readonly buffer SgLightGrid {
  SgLightGridHeader sgLightGridHeader;
  uint sgLightGridData[];
};

// Lights `count` of them: light k is sgLights[k], or, when `cluster` is not
// ~0u, sgLights[the k-th index of that cluster].
struct SgLightList {
  uint cluster;  // start of the cluster's record in sgLightGridData, or ~0u: every light
  uint count;
};

// The lights that may reach `position`: its cluster's when the frame has a
// grid and the position is inside it, else every light. Positions outside the
// grid (off screen, nearer or farther than any visible draw: a decoupled
// object's shadels beyond the screen edge) loop over every light, so the
// result never depends on the grid, only its cost.
SgLightList sgLightsAt(vec3 position) {
  SgLightList every = SgLightList(~0u, frame.counts.x);
#ifdef SG_NO_LIGHT_GRID
  return every;  // the frame built no grid (its stand-in says "every light" too)
#endif
  uvec4 dims = sgLightGridHeader.dims;
  if (dims.w == 0u) return every;
  vec4 clip = frame.viewProjection * vec4(position, 1.0);
  vec4 depth = sgLightGridHeader.depth;
  if (!(clip.w >= depth.x && clip.w <= depth.y)) return every;
  vec2 ndc = clip.xy / clip.w;
  if (any(greaterThan(abs(ndc), vec2(1.0)))) return every;
  uvec2 tile = min(uvec2((ndc * 0.5 + 0.5) * vec2(dims.xy)), dims.xy - 1u);
  uint slice = min(uint(max(log(clip.w / depth.x) * depth.z, 0.0)), dims.z - 1u);
  uint record = ((slice * dims.y + tile.y) * dims.x + tile.x) * (dims.w + 1u);
  uint count = sgLightGridData[record];
  return count == kLightGridEveryLight ? every : SgLightList(record, count);
}

Light sgLight(SgLightList list, uint k) {
  return sgLights[list.cluster == ~0u ? k : sgLightGridData[list.cluster + 1u + k]];
}

// The shadow atlas (passes/shadows): the maps of the shadowed lights,
// frame.shadowAtlas.z maps a row; map s's matrix is frame.shadowMatrices[s].
layout(set = 0, binding = kBindShadowMaps) uniform sampler2D sgShadowMaps;

// How much light map `slot` lets reach `position`, 0..1 (1 outside the map):
// 3x3 bilinear PCF (16 depth compares, weights 1-f, 1, 1, f per axis). The
// maps carry the slope-scaled bias (written when they are drawn), so a
// receiver compares its own depth.
float sgShadowMapAt(int slot, vec3 position) {
  vec4 clip = frame.shadowMatrices[slot] * vec4(position, 1.0);
  if (clip.w <= 0.0) return 1.0;  // behind the light: outside its cone anyway
  vec3 ndc = clip.xyz / clip.w;
  if (any(greaterThan(abs(ndc.xy), vec2(1.0))) || ndc.z > 1.0) return 1.0;
  int size = int(frame.shadowAtlas.y), columns = max(int(frame.shadowAtlas.z), 1);
  ivec2 origin = ivec2(slot % columns, slot / columns) * size;
  // The map is drawn with +Y up (negative-height viewport): row 0 is ndc.y = +1.
  vec2 texel = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * float(size) - 0.5;
  vec2 base = floor(texel), f = texel - base;
  // Clamped to the bound image too: a frame whose maps were not drawn binds a 1x1 white stand-in.
  ivec2 last = textureSize(sgShadowMaps, 0) - 1;
  float lit = 0.0;
  for (int y = 0; y < 4; ++y) {
    float wy = y == 0 ? 1.0 - f.y : (y == 3 ? f.y : 1.0);
    for (int x = 0; x < 4; ++x) {
      float wx = x == 0 ? 1.0 - f.x : (x == 3 ? f.x : 1.0);
      ivec2 t = clamp(ivec2(base) + ivec2(x - 1, y - 1), ivec2(0), ivec2(size - 1));
      float stored = texelFetch(sgShadowMaps, min(origin + t, last), 0).r;
      lit += ndc.z <= stored ? wx * wy : 0.0;
    }
  }
  return lit / 9.0;
}

// How much of a shadowed light reaches `position`, 0..1. Spot: its map.
// Point: the cube face of the major axis. Directional: the cascade of the
// position's view depth, blended into the next over the last kCascadeBlend of
// it (the next cascade covers that band too), so the boundary does not pop.
// At most two map lookups, each behind a loop that runs 0 or 1 times: lavapipe
// runs an if's body under a lane mask even when no lane takes it, but skips a
// loop that no lane enters (a lookup per cascade and light type cost the default
// scene's forward-opaque 1.45x, 34% more shader instructions under callgrind).
float sgShadowAt(Light light, vec3 position) {
#ifdef SG_NO_SHADOW_MAPS
  // The frame draws no shadow map (no light has one): the code below would
  // return 1 too, but lavapipe measured slower with the untaken code compiled in.
  return 1.0;
#endif
  int first = int(light.cone.z) - 1;
  float lit = 1.0;
  for (int shadowed = first >= 0 ? 1 : 0; shadowed > 0; --shadowed) {
    uint type = uint(light.positionType.w);
    // Far from the origin a float position is only good to its last bits, and so
    // are the caster depths in the maps: the receiver steps 2 ulps of its largest
    // coordinate towards the light (nothing near the origin: 1 um at 4 units).
    vec3 a = abs(position);
    float ulps = 2.0 * max(a.x, max(a.y, a.z)) * 1.1920929e-7;
    vec3 towards = type == SG_LIGHT_DIRECTIONAL ? -light.directionRange.xyz : light.positionType.xyz - position;
    vec3 p = position + ulps * towards / max(length(towards), 1e-30);
    int slot = first, blendSlot = first;
    float blend = 0.0;
    if (type == SG_LIGHT_POINT) {
      vec3 d = p - light.positionType.xyz, m = abs(d);
      slot += m.x >= m.y && m.x >= m.z ? (d.x >= 0.0 ? 0 : 1) : (m.y >= m.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5));
    } else if (type == SG_LIGHT_DIRECTIONAL) {
      float depth = -(frame.view * vec4(p, 1.0)).z;
      vec4 ends = light.cascadeEnds;
      int c = int(dot(vec4(greaterThan(vec4(depth), ends)), vec4(1.0)));  // cascades ending before it
      float start = c == 0 ? 0.0 : ends[max(c - 1, 0)], end = ends[min(c, int(kShadowCascades) - 1)];
      float band = kCascadeBlend * (end - start);
      slot = c < int(kShadowCascades) ? first + c : -1;  // -1: beyond the farthest visible object
      blendSlot = slot + 1;
      blend = c + 1 < int(kShadowCascades) ? clamp((depth - (end - band)) / band, 0.0, 1.0) : 0.0;
    }
    for (int inside = slot >= 0 ? 1 : 0; inside > 0; --inside) lit = sgShadowMapAt(slot, p);
    for (int blended = blend > 0.0 ? 1 : 0; blended > 0; --blended) lit = mix(lit, sgShadowMapAt(blendSlot, p), blend);
  }
  return lit;
}

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
  if (attenuation > 0.0) attenuation *= sgShadowAt(light, position);
  return LightSample(L, light.color.rgb * attenuation);
}

#endif
