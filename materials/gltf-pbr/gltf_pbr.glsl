// glTF metallic-roughness shading of one surface point with the frame's
// punctual lights (the SDK's sgLightAt) and the environment: the scene's
// prefiltered HDR image when it names one, else a hemispherical sky.
// Textures are sampled with the surface's UV derivatives (materialSample),
// whichever variant runs it.
#ifndef SG_GLTF_PBR_GLSL
#define SG_GLTF_PBR_GLSL

#include <framework/plugin/shaders/material.glsl>
#include "brdf.glsl"

vec4 materialBaseColor(Surface s) {
  vec4 c = material.baseColorFactor * s.color;
  if (materialHas(SG_TEX_BASE_COLOR)) c *= materialSample(baseColorTexture, SG_TEX_BASE_COLOR, s);
  return c;
}

// The surface normal perturbed by a tangent-space normal-map texel `texel` (0..1) at `scale`.
vec3 tangentSpaceNormal(Surface s, vec3 texel, float scale) {
  vec3 t = s.tangent.xyz - s.normal * dot(s.normal, s.tangent.xyz);
  if (dot(t, t) < 1e-12) return s.normal;
  t = normalize(t);
  vec3 b = cross(s.normal, t) * s.tangent.w;
  vec3 m = texel * 2.0 - 1.0;
  m.xy *= scale;
  return normalize(mat3(t, b, s.normal) * m);
}

vec3 shadingNormal(Surface s) {
  if (!materialHas(SG_TEX_NORMAL)) return s.normal;
  return tangentSpaceNormal(s, materialSample(normalTexture, SG_TEX_NORMAL, s).xyz, material.emissiveFactor.w);
}

// Radiance (cd/m^2) of the analytic sky seen in a direction with vertical component `y`:
// frame.ambient is the zenith (render::skyLuminance), the horizon 1.6x, the ground 0.3x.
vec3 environmentRadiance(float y) {
  vec3 sky = frame.ambient.rgb, horizon = frame.ambient.rgb * 1.6, ground = frame.ambient.rgb * 0.3;
  return y > 0.0 ? mix(horizon, sky, sqrt(y)) : mix(horizon, ground, sqrt(-y));
}

// The environment's radiance around N, cosine-weighted (irradiance / pi): the
// scene's environment image when it has one, else the analytic sky gradient.
// One source for every variant (forward, decoupled, the split-pbr layers).
vec3 ambientDiffuse(vec3 N) {
#ifndef SG_NO_ENVIRONMENT_MAPS  // the frame has no prefiltered maps: the sky only
  if (frame.environment.x > 0.0) return sgEnvironmentDiffuse(N);
#endif
  return environmentRadiance(N.y);
}

// The environment's specular reflection along R (reflect(-V, N)) for f0 at
// N.V, before occlusion: the prefiltered image times the split-sum BRDF
// lookup, or the analytic sky blurred towards its average with roughness,
// scaled by Karis' analytic split-sum fit (UE4 mobile).
vec3 ambientSpecular(vec3 R, float NdotV, float roughness, vec3 f0, float f90) {
#ifndef SG_NO_ENVIRONMENT_MAPS
  if (frame.environment.x > 0.0) {
    vec2 ab = sgEnvironmentBrdf(NdotV, roughness);
    return sgEnvironmentSpecular(R, roughness) * (f0 * ab.x + f90 * ab.y);
  }
#endif
  vec3 specularEnv = mix(environmentRadiance(R.y), environmentRadiance(0.3), roughness * roughness);
  vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022), c1 = vec4(1.0, 0.0425, 1.04, -0.04);
  vec4 r = roughness * c0 + c1;
  float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
  return specularEnv * (f0 * ab.x + f90 * ab.y);
}

vec3 ambientSpecular(vec3 R, float NdotV, float roughness, vec3 f0) { return ambientSpecular(R, NdotV, roughness, f0, 1.0); }

// The glTF metallic-roughness model at a surface point for given inputs:
// what shadeGltfPbr and layers with their own inputs (marble, bumps) share.
// N: the shading normal. rgb = outgoing radiance towards the camera.
// dielectricF0, dielectricF90: the dielectric Fresnel (0.04 and 1 unless KHR_materials_ior /
// KHR_materials_specular say otherwise).
vec3 shadeMetallicRoughness(Surface s, vec3 baseColor, float metallic, float roughness, float occlusion,
                            vec3 emissive, vec3 N, vec3 dielectricF0, float dielectricF90) {
  vec3 V = normalize(frame.cameraPosition.xyz - s.position);
  vec3 color = vec3(0.0);
  SgLightList lights = sgLightsAt(s.position);
  for (uint k = 0u; k < lights.count; ++k) {
    LightSample light = sgLightAt(sgLight(lights, k), s.position);
    color += brdfGltf(baseColor, metallic, roughness, dielectricF0, dielectricF90, N, V, light.direction, light.radiance);
  }
  float NdotV = clamp(dot(N, V), 1e-4, 1.0);
  vec3 f0 = mix(dielectricF0, baseColor, metallic);
  float f90 = mix(dielectricF90, 1.0, metallic);
  color += occlusion * (ambientDiffuse(N) * baseColor * (1.0 - metallic) +
                        ambientSpecular(reflect(-V, N), NdotV, roughness, f0, f90));
  return color + emissive;
}

vec3 shadeMetallicRoughness(Surface s, vec3 baseColor, float metallic, float roughness, float occlusion,
                            vec3 emissive, vec3 N) {
  return shadeMetallicRoughness(s, baseColor, metallic, roughness, occlusion, emissive, N, vec3(0.04), 1.0);
}

// The material's occlusion (1: none), what the layers on top of gltf-pbr also apply to their environment light.
float materialOcclusion(Surface s) {
  if (!materialHas(SG_TEX_OCCLUSION)) return 1.0;
  return 1.0 + material.params.z * (materialSample(occlusionTexture, SG_TEX_OCCLUSION, s).r - 1.0);
}

vec3 materialEmissive(Surface s) {
  vec3 emissive = material.emissiveFactor.rgb;
  if (materialHas(SG_TEX_EMISSIVE)) emissive *= materialSample(emissiveTexture, SG_TEX_EMISSIVE, s).rgb;
  return emissive;
}

// The glTF material with a given dielectric Fresnel: rgb = outgoing radiance towards the camera, a = alpha.
vec4 shadeGltfPbrWithFresnel(Surface s, vec3 dielectricF0, float dielectricF90) {
  vec4 baseColor = materialBaseColor(s);
  if (material.flags.w != 0u) return baseColor;  // KHR_materials_unlit
  float metallic = material.params.x, roughness = material.params.y;
  if (materialHas(SG_TEX_METALLIC_ROUGHNESS)) {
    vec4 mr = materialSample(metallicRoughnessTexture, SG_TEX_METALLIC_ROUGHNESS, s);
    roughness *= mr.g;
    metallic *= mr.b;
  }
  vec3 color = shadeMetallicRoughness(s, baseColor.rgb, metallic, roughness, materialOcclusion(s), materialEmissive(s),
                                      shadingNormal(s), dielectricF0, dielectricF90);
  return vec4(color, baseColor.a);
}

// The glTF material layer.
vec4 shadeGltfPbr(Surface s) { return shadeGltfPbrWithFresnel(s, vec3(0.04), 1.0); }

#endif
