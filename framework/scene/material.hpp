#pragma once
// glTF 2.0 metallic-roughness material.
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
};

}  // namespace sg::scene
