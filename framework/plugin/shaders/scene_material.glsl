// The scene material of the object being shaded: the glTF metallic-roughness
// constants and textures GpuScene uploads, bound as descriptor set 1 (one set
// per material), and helpers to sample its textures at a Surface with the
// surface's derivatives. Mirrors GpuMaterial in framework/render/gpu_scene.cpp.
// Part of the material SDK (framework/plugin/shaders/material.glsl).
#ifndef SG_SCENE_MATERIAL_GLSL
#define SG_SCENE_MATERIAL_GLSL

#include <framework/plugin/shaders/surface.glsl>

#define SG_ALPHA_OPAQUE 0u
#define SG_ALPHA_MASK 1u
#define SG_ALPHA_BLEND 2u

// Texture slots, in binding order 1..12: the core material's, then the
// material extensions' (KHR_materials_clearcoat, _sheen, _specular).
#define SG_TEX_BASE_COLOR 0
#define SG_TEX_METALLIC_ROUGHNESS 1
#define SG_TEX_NORMAL 2
#define SG_TEX_OCCLUSION 3
#define SG_TEX_EMISSIVE 4
#define SG_TEX_CLEARCOAT 5
#define SG_TEX_CLEARCOAT_ROUGHNESS 6
#define SG_TEX_CLEARCOAT_NORMAL 7
#define SG_TEX_SHEEN_COLOR 8
#define SG_TEX_SHEEN_ROUGHNESS 9
#define SG_TEX_SPECULAR 10
#define SG_TEX_SPECULAR_COLOR 11

struct TextureSlot {
  vec4 row0;   // KHR_texture_transform, first row of the 2x3 affine
  vec4 row1;   // second row; w = UV set (0 or 1)
};

layout(set = 1, binding = 0, std140) uniform MaterialBlock {
  vec4 baseColorFactor;
  vec4 emissiveFactor;  // rgb, w = normal scale
  vec4 params;          // x = metallic, y = roughness, z = occlusion strength, w = alpha cutoff
  uvec4 flags;          // x = alpha mode, y = double sided, z = bitmask of present textures, w = unlit
  vec4 clearcoat;       // x = factor, y = roughness, z = clear-coat normal scale
  vec4 sheen;           // rgb = colour, w = roughness
  vec4 specular;        // rgb = specularColorFactor x ((ior - 1) / (ior + 1))^2, w = specularFactor
  TextureSlot slots[12];
} material;

layout(set = 1, binding = 1) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 2) uniform sampler2D metallicRoughnessTexture;
layout(set = 1, binding = 3) uniform sampler2D normalTexture;
layout(set = 1, binding = 4) uniform sampler2D occlusionTexture;
layout(set = 1, binding = 5) uniform sampler2D emissiveTexture;
layout(set = 1, binding = 6) uniform sampler2D clearcoatTexture;
layout(set = 1, binding = 7) uniform sampler2D clearcoatRoughnessTexture;
layout(set = 1, binding = 8) uniform sampler2D clearcoatNormalTexture;
layout(set = 1, binding = 9) uniform sampler2D sheenColorTexture;
layout(set = 1, binding = 10) uniform sampler2D sheenRoughnessTexture;
layout(set = 1, binding = 11) uniform sampler2D specularTexture;
layout(set = 1, binding = 12) uniform sampler2D specularColorTexture;

bool materialHas(int slot) {
#ifdef SG_FORWARD_PLAIN
  // A plain forward draw's material has none of the core textures
  // (DrawItem::plainSurface): lavapipe runs both sides of a branch, so the
  // untaken texture reads would cost every pixel (issue 14: 0.85x forward-opaque).
  if (slot <= SG_TEX_EMISSIVE) return false;
#endif
  return (material.flags.z & (1u << slot)) != 0u;
}

vec2 materialUv(int slot, vec2 uv0, vec2 uv1) {
  TextureSlot s = material.slots[slot];
  vec2 uv = s.row1.w > 0.5 ? uv1 : uv0;
  return vec2(dot(s.row0.xyz, vec3(uv, 1.0)), dot(s.row1.xyz, vec3(uv, 1.0)));
}

// A UV derivative through the slot's transform (its linear part only).
vec2 materialUvDelta(int slot, vec2 d0, vec2 d1) {
  TextureSlot s = material.slots[slot];
  vec2 d = s.row1.w > 0.5 ? d1 : d0;
  return vec2(dot(s.row0.xy, d), dot(s.row1.xy, d));
}

// Samples a material texture at the surface with explicit derivatives.
vec4 materialSample(sampler2D tex, int slot, Surface s) {
  return textureGrad(tex, materialUv(slot, s.uv0, s.uv1), materialUvDelta(slot, s.uv0Dx, s.uv1Dx),
                     materialUvDelta(slot, s.uv0Dy, s.uv1Dy));
}

#endif
