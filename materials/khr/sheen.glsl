// A KHR_materials_sheen layer on the shaded base SHEEN_BASE (a parameter: the
// layer under it): the Charlie microfibre lobe of Conty & Kulla 2017 (the
// extension's distribution and visibility), combined by albedo scaling with
// the view term only, as the extension allows:
//   f = f_sheen + base * (1 - max3(sheenColor) * E(N.V)).
// The base's emission is not scaled (the Sample Viewer adds it after the
// sheen). The environment's sheen is the diffuse environment times the
// lobe's directional albedo E (three.js's approximation).
#include <materials/gltf-pbr/gltf_pbr.glsl>

#ifndef SG_SHEEN_BRDF_GLSL
#define SG_SHEEN_BRDF_GLSL

// alphaG = sheenRoughness^2, as the Khronos Sample Viewer does.
float sheenDistribution(float alphaG, float NdotH) {
  float invR = 1.0 / alphaG;
  float sin2h = max(1.0 - NdotH * NdotH, 0.0);
  return (2.0 + invR) * pow(sin2h, invR * 0.5) / (2.0 * kPi);
}

float sheenLambdaFit(float x, float alphaG) {
  float t = (1.0 - alphaG) * (1.0 - alphaG);
  float a = mix(21.5473, 25.3245, t), b = mix(3.82987, 3.32435, t), c = mix(0.19823, 0.16801, t);
  float d = mix(-1.97760, -1.27393, t), e = mix(-4.32054, -4.85967, t);
  return a / (1.0 + b * pow(x, c)) + d * x + e;
}

float sheenLambda(float cosTheta, float alphaG) {
  return cosTheta < 0.5 ? exp(sheenLambdaFit(cosTheta, alphaG))
                        : exp(2.0 * sheenLambdaFit(0.5, alphaG) - sheenLambdaFit(1.0 - cosTheta, alphaG));
}

float sheenVisibility(float NdotL, float NdotV, float alphaG) {
  return clamp(1.0 / ((1.0 + sheenLambda(NdotV, alphaG) + sheenLambda(NdotL, alphaG)) * (4.0 * NdotV * NdotL)), 0.0, 1.0);
}

// E(N.V): the Charlie lobe's directional albedo, a curve fit over roughness (three.js, IBLSheenBRDF times pi).
float sheenAlbedo(float NdotV, float roughness) {
  float r = clamp(roughness, 0.07, 1.0), r2 = r * r;
  float a = r < 0.25 ? -339.2 * r2 + 161.4 * r - 25.9 : -8.48 * r2 + 14.3 * r - 9.95;
  float b = r < 0.25 ? 44.0 * r2 - 23.7 * r + 3.26 : 1.97 * r2 - 3.27 * r + 0.72;
  return clamp(exp(a * NdotV + b) + (r < 0.25 ? 0.0 : 0.1 * (r - 0.25)), 0.0, 1.0);
}

#endif

vec4 sheenLayer(Surface s) {
  vec4 base = sgLayer(SHEEN_BASE);
  if (material.flags.w != 0u) return base;  // KHR_materials_unlit: nothing lit to layer on
  vec3 color = material.sheen.rgb;
  if (materialHas(SG_TEX_SHEEN_COLOR)) color *= materialSample(sheenColorTexture, SG_TEX_SHEEN_COLOR, s).rgb;
  float roughness = material.sheen.w;
  if (materialHas(SG_TEX_SHEEN_ROUGHNESS)) roughness *= materialSample(sheenRoughnessTexture, SG_TEX_SHEEN_ROUGHNESS, s).a;
  float alphaG = max(roughness * roughness, 1e-6);
  vec3 N = shadingNormal(s), V = normalize(frame.cameraPosition.xyz - s.position);
  float NdotV = clamp(dot(N, V), 1e-4, 1.0);
  vec3 sheen = vec3(0.0);
  SgLightList lights = sgLightsAt(s.position);
  for (uint k = 0u; k < lights.count; ++k) {
    LightSample light = sgLightAt(sgLight(lights, k), s.position);
    float NdotL = dot(N, light.direction);
    if (NdotL <= 0.0) continue;
    float NdotH = clamp(dot(N, normalize(V + light.direction)), 0.0, 1.0);
    sheen += color * sheenDistribution(alphaG, NdotH) * sheenVisibility(NdotL, NdotV, alphaG) * NdotL * light.radiance;
  }
  float albedo = sheenAlbedo(NdotV, roughness);
  sheen += materialOcclusion(s) * ambientDiffuse(N) * color * albedo;
  float scaling = 1.0 - max(max(color.r, color.g), color.b) * albedo;
  vec3 emissive = materialEmissive(s);
  return vec4(sheen + (base.rgb - emissive) * scaling + emissive, base.a);
}
