// A KHR_materials_clearcoat layer on the shaded base CLEARCOAT_BASE (a
// parameter: the layer under it): a GGX coat with f0 0.04 (ior 1.5), its own
// roughness and normal (the geometric normal unless clearcoatNormalTexture is
// given, not the base's normal map), over the base weighted by the coat's
// Fresnel, as the extension specifies:
//   f = base * (1 - clearcoat * F_coat(N_c.V)) + clearcoat * f_coat.
// The base's emission is attenuated the same way (the extension and the
// Sample Viewer do so).
#include <materials/gltf-pbr/gltf_pbr.glsl>

vec4 clearcoatLayer(Surface s) {
  vec4 base = sgLayer(CLEARCOAT_BASE);
  if (material.flags.w != 0u) return base;  // KHR_materials_unlit: nothing lit to layer on
  float factor = material.clearcoat.x;
  if (materialHas(SG_TEX_CLEARCOAT)) factor *= materialSample(clearcoatTexture, SG_TEX_CLEARCOAT, s).r;
  float roughness = material.clearcoat.y;
  if (materialHas(SG_TEX_CLEARCOAT_ROUGHNESS))
    roughness *= materialSample(clearcoatRoughnessTexture, SG_TEX_CLEARCOAT_ROUGHNESS, s).g;
  vec3 N = s.normal;
  if (materialHas(SG_TEX_CLEARCOAT_NORMAL))
    N = tangentSpaceNormal(s, materialSample(clearcoatNormalTexture, SG_TEX_CLEARCOAT_NORMAL, s).xyz, material.clearcoat.z);
  vec3 V = normalize(frame.cameraPosition.xyz - s.position);
  float NdotV = clamp(dot(N, V), 1e-4, 1.0);
  float alpha = max(roughness * roughness, 1e-3);
  vec3 coat = vec3(0.0);
  SgLightList lights = sgLightsAt(s.position);
  for (uint k = 0u; k < lights.count; ++k) {
    LightSample light = sgLightAt(sgLight(lights, k), s.position);
    float NdotL = clamp(dot(N, light.direction), 0.0, 1.0);
    vec3 H = normalize(V + light.direction);
    float F = fresnelSchlick(vec3(0.04), 1.0, clamp(dot(V, H), 0.0, 1.0)).x;
    coat += F * distributionGgx(clamp(dot(N, H), 0.0, 1.0), alpha) * visibilitySmithGgx(NdotL, NdotV, alpha) * NdotL *
            light.radiance;
  }
  coat += materialOcclusion(s) * ambientSpecular(reflect(-V, N), NdotV, roughness, vec3(0.04), 1.0);
  float coatFresnel = fresnelSchlick(vec3(0.04), 1.0, NdotV).x;
  return vec4(base.rgb * (1.0 - factor * coatFresnel) + factor * coat, base.a);
}
