// Layer "diffuse-light" (view-independent, dependsOn World): what glTF PBR
// reflects diffusely, Lambert from the punctual lights plus the diffuse
// environment, and the emission; rgb = that radiance, a = alpha. Nothing here
// reads the camera, so its value holds while the object and lights stay put.
// (The Fresnel weight (1 - F) of the full model depends on the view; this
// split leaves it out, as many real-time renderers do.)
#ifndef SG_DIFFUSE_LIGHT_GLSL
#define SG_DIFFUSE_LIGHT_GLSL

#include <materials/gltf-pbr/gltf_pbr.glsl>

// The material's inputs at a surface point, shared by both layers.
struct SplitInputs {
  vec4 baseColor;
  float metallic, roughness, occlusion;
  vec3 emissive, N;
};

SplitInputs splitInputs(Surface s) {
  SplitInputs m;
  m.baseColor = materialBaseColor(s);
  m.metallic = material.params.x;
  m.roughness = material.params.y;
  if (materialHas(SG_TEX_METALLIC_ROUGHNESS)) {
    vec4 mr = materialSample(metallicRoughnessTexture, SG_TEX_METALLIC_ROUGHNESS, s);
    m.roughness *= mr.g;
    m.metallic *= mr.b;
  }
  m.occlusion = 1.0;
  if (materialHas(SG_TEX_OCCLUSION))
    m.occlusion = 1.0 + material.params.z * (materialSample(occlusionTexture, SG_TEX_OCCLUSION, s).r - 1.0);
  m.emissive = material.emissiveFactor.rgb;
  if (materialHas(SG_TEX_EMISSIVE)) m.emissive *= materialSample(emissiveTexture, SG_TEX_EMISSIVE, s).rgb;
  m.N = shadingNormal(s);
  return m;
}

vec4 diffuseLight(Surface s) {
  SplitInputs m = splitInputs(s);
  if (material.flags.w != 0u) return m.baseColor;  // KHR_materials_unlit
  vec3 albedo = m.baseColor.rgb * (1.0 - m.metallic);
  vec3 color = vec3(0.0);
  SgLightList lights = sgLightsAt(s.position);
  for (uint k = 0u; k < lights.count; ++k) {
    LightSample light = sgLightAt(sgLight(lights, k), s.position);
    color += albedo / kPi * light.radiance * clamp(dot(m.N, light.direction), 0.0, 1.0);
  }
  color += m.occlusion * ambientDiffuse(m.N) * albedo;
  return vec4(color + m.emissive, m.baseColor.a);
}

#endif
