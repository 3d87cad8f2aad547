// The alpha test of alpha-mask materials (glTF alphaMode MASK), one function
// for every pass that draws them: forward (alpha-mask), and for decoupled
// objects the z-prepass, shadel-mark and composite, so that all of them keep
// exactly the same pixels. The coverage is the base colour's alpha
// (baseColorFactor.a x COLOR_0.a x the base colour texture's alpha at the
// pixel), against alphaCutoff (material.params.w). Fragment shaders only
// (implicit derivatives); needs the scene material (set 1).
#ifndef SG_ALPHA_TEST_GLSL
#define SG_ALPHA_TEST_GLSL

#include <framework/plugin/shaders/scene_material.glsl>

float sgMaskCoverage(vec2 uv0, vec2 uv1, float colorAlpha) {
  float alpha = material.baseColorFactor.a * colorAlpha;
  if (materialHas(SG_TEX_BASE_COLOR)) alpha *= texture(baseColorTexture, materialUv(SG_TEX_BASE_COLOR, uv0, uv1)).a;
  return alpha;
}

// True where an alpha-mask material cuts the surface away (never for other modes).
bool sgMaskedOut(vec2 uv0, vec2 uv1, float colorAlpha) {
  return material.flags.x == SG_ALPHA_MASK && sgMaskCoverage(uv0, uv1, colorAlpha) < material.params.w;
}

#endif
