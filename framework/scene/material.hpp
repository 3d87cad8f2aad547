#pragma once
// glTF 2.0 metallic-roughness material.
#include <array>
#include <optional>
#include <string>

#include <glm/glm.hpp>

namespace sg::scene {

enum class AlphaMode { Opaque, Mask, Blend };

// KHR_texture_transform: uv' = translate(offset) * rotate(rotation) * scale(scale) * uv.
struct TextureTransform {
  glm::vec2 offset{0.0f};
  float rotation = 0.0f;  // radians, counter-clockwise in UV space as the extension defines it
  glm::vec2 scale{1.0f};

  bool isIdentity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
  // The 3x3 matrix the extension specifies, to multiply vec3(uv, 1).
  glm::mat3 matrix() const;
};

struct TextureRef {
  int texture = -1;  // index into Scene::textures; -1: no texture
  int texCoord = 0;  // UV set, with KHR_texture_transform's texCoord override already applied
  TextureTransform transform;

  bool present() const { return texture >= 0; }
};

// KHR_materials_clearcoat: a GGX coat (f0 0.04) over the base, with its own roughness and normal.
struct Clearcoat {
  float factor = 0.0f;
  float roughnessFactor = 0.0f;
  TextureRef texture;           // linear, R scales factor
  TextureRef roughnessTexture;  // linear, G scales roughnessFactor
  TextureRef normalTexture;     // linear, tangent space; absent: the geometric normal (not the base's normal map)
  float normalScale = 1.0f;
};

// KHR_materials_sheen: a Charlie microfibre lobe over the base.
struct Sheen {
  glm::vec3 colorFactor{0.0f};
  float roughnessFactor = 0.0f;
  TextureRef colorTexture;      // sRGB, rgb scales colorFactor
  TextureRef roughnessTexture;  // linear, A scales roughnessFactor
};

// KHR_materials_specular: the strength and colour of the dielectric Fresnel.
struct Specular {
  float factor = 1.0f;
  glm::vec3 colorFactor{1.0f};
  TextureRef texture;       // linear, A scales factor
  TextureRef colorTexture;  // sRGB, rgb scales colorFactor
};

struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  float metallicFactor = 1.0f;
  float roughnessFactor = 1.0f;
  glm::vec3 emissiveFactor{0.0f};
  float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength: scales emissiveFactor (nits per unit)
  TextureRef baseColorTexture;          // sRGB
  TextureRef metallicRoughnessTexture;  // linear; B = metal, G = roughness
  TextureRef normalTexture;             // linear, tangent space, +Y up
  float normalScale = 1.0f;
  TextureRef occlusionTexture;  // linear, R
  float occlusionStrength = 1.0f;
  TextureRef emissiveTexture;  // sRGB
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;  // used by AlphaMode::Mask only
  bool doubleSided = false;
  bool unlit = false;  // KHR_materials_unlit: the base colour is the radiance, no lighting
  // The material extensions shaded as layers on gltf-pbr (materials/khr, docs/scene-format.md); absent: not used.
  std::optional<float> ior;  // KHR_materials_ior: the dielectric's index of refraction (glTF's default is 1.5)
  std::optional<Specular> specular;
  std::optional<Sheen> sheen;
  std::optional<Clearcoat> clearcoat;

  // Its textures in the GPU's slot order (SG_TEX_* in framework/plugin/shaders/scene_material.glsl):
  // the core five, then the extensions' (empty where an extension is absent).
  std::array<TextureRef, 12> textureSlots() const {
    const Clearcoat c = clearcoat.value_or(Clearcoat{});
    const Sheen s = sheen.value_or(Sheen{});
    const Specular p = specular.value_or(Specular{});
    return {baseColorTexture, metallicRoughnessTexture, normalTexture, occlusionTexture, emissiveTexture,
            c.texture, c.roughnessTexture, c.normalTexture, s.colorTexture, s.roughnessTexture, p.texture, p.colorTexture};
  }
  // Calls f(TextureRef&) on every texture reference it has, the extensions' included.
  template <class F>
  void forEachTexture(F&& f) {
    for (TextureRef* ref : {&baseColorTexture, &metallicRoughnessTexture, &normalTexture, &occlusionTexture, &emissiveTexture})
      f(*ref);
    if (clearcoat) for (TextureRef* ref : {&clearcoat->texture, &clearcoat->roughnessTexture, &clearcoat->normalTexture}) f(*ref);
    if (sheen) for (TextureRef* ref : {&sheen->colorTexture, &sheen->roughnessTexture}) f(*ref);
    if (specular) for (TextureRef* ref : {&specular->texture, &specular->colorTexture}) f(*ref);
  }
};

}  // namespace sg::scene
