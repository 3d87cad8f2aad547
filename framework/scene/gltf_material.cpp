#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <shadelgraph/scene/gltf_material.hpp>
#include <shadelgraph/scene/image_decode.hpp>

namespace sg::scene::detail {
namespace {

WrapMode toWrapMode(int wrap, std::vector<std::string>& warnings, const std::string& where) {
  switch (wrap) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return WrapMode::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return WrapMode::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return WrapMode::MirroredRepeat;
    default: warnings.push_back(where + ": unknown wrap mode " + std::to_string(wrap) + ", using REPEAT"); return WrapMode::Repeat;
  }
}

Sampler toSampler(const tinygltf::Sampler& in, std::vector<std::string>& warnings, const std::string& where) {
  Sampler out;
  out.wrapS = toWrapMode(in.wrapS, warnings, where);
  out.wrapT = toWrapMode(in.wrapT, warnings, where);
  switch (in.magFilter) {
    case -1: break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST: out.magFilter = Filter::Nearest; break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: out.magFilter = Filter::Linear; break;
    default: warnings.push_back(where + ": unknown magFilter " + std::to_string(in.magFilter) + ", using LINEAR");
  }
  const std::map<int, std::pair<Filter, MipmapMode>> minFilters{
      {TINYGLTF_TEXTURE_FILTER_NEAREST, {Filter::Nearest, MipmapMode::None}},
      {TINYGLTF_TEXTURE_FILTER_LINEAR, {Filter::Linear, MipmapMode::None}},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST, {Filter::Nearest, MipmapMode::Nearest}},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST, {Filter::Linear, MipmapMode::Nearest}},
      {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR, {Filter::Nearest, MipmapMode::Linear}},
      {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR, {Filter::Linear, MipmapMode::Linear}},
  };
  if (const auto it = minFilters.find(in.minFilter); it != minFilters.end())
    std::tie(out.minFilter, out.mipmapMode) = it->second;
  else if (in.minFilter != -1)
    warnings.push_back(where + ": unknown minFilter " + std::to_string(in.minFilter) + ", using LINEAR_MIPMAP_LINEAR");
  return out;
}

float number(const tinygltf::Value& value, float fallback) {
  return value.IsNumber() ? static_cast<float>(value.GetNumberAsDouble()) : fallback;
}

glm::vec2 vec2(const tinygltf::Value& value, glm::vec2 fallback) {
  if (!value.IsArray() || value.ArrayLen() != 2) return fallback;
  return {number(value.Get(0), fallback.x), number(value.Get(1), fallback.y)};
}

template <size_t N>
glm::vec<N, float> factor(const std::vector<double>& values, float fallback) {
  glm::vec<N, float> out(fallback);
  for (size_t i = 0; i < N && i < values.size(); ++i) out[static_cast<int>(i)] = static_cast<float>(values[i]);
  return out;
}

// Builds scene textures on demand, one per (glTF texture, colour space), and
// decodes each used image once.
class TextureBuilder {
 public:
  TextureBuilder(const GltfContext& context, Scene& scene) : context_(context), scene_(scene) {
    const tinygltf::Model& model = context.model;
    for (size_t i = 0; i < model.samplers.size(); ++i)
      scene.samplers.push_back(toSampler(model.samplers[i], context.warnings, describe("sampler", i, model.samplers[i].name)));
  }

  // `where` names the use, e.g. "material 0 'Red' baseColorTexture".
  TextureRef reference(int textureIndex, int texCoord, const tinygltf::ExtensionMap& extensions, bool srgb,
                       const std::string& where) {
    const auto it = extensions.find("KHR_texture_transform");
    return reference(textureIndex, texCoord, it != extensions.end() ? &it->second : nullptr, srgb, where);
  }

  // A textureInfo inside a material extension (tinygltf leaves those as JSON values).
  TextureRef reference(const tinygltf::Value& info, bool srgb, const std::string& where) {
    if (!info.IsObject()) return {};
    const tinygltf::Value& index = info.Get("index");
    const tinygltf::Value& texCoord = info.Get("texCoord");
    const tinygltf::Value& extensions = info.Get("extensions");
    const tinygltf::Value* transform =
        extensions.IsObject() && extensions.Has("KHR_texture_transform") ? &extensions.Get("KHR_texture_transform") : nullptr;
    if (!index.IsInt() || index.GetNumberAsInt() < 0) throw InvalidAsset(where + ": index must be an integer >= 0");
    return reference(index.GetNumberAsInt(), texCoord.IsInt() ? texCoord.GetNumberAsInt() : 0, transform, srgb, where);
  }

 private:
  TextureRef reference(int textureIndex, int texCoord, const tinygltf::Value* transformValue, bool srgb,
                       const std::string& where) {
    TextureRef ref;
    if (textureIndex < 0) return ref;
    ref.texture = texture(textureIndex, srgb, where);
    ref.texCoord = texCoord;
    if (transformValue && transformValue->IsObject()) {
      const tinygltf::Value& transform = *transformValue;
      ref.transform.offset = vec2(transform.Get("offset"), glm::vec2(0.0f));
      ref.transform.rotation = number(transform.Get("rotation"), 0.0f);
      ref.transform.scale = vec2(transform.Get("scale"), glm::vec2(1.0f));
      if (transform.Get("texCoord").IsInt()) ref.texCoord = transform.Get("texCoord").GetNumberAsInt();
    }
    if (ref.texCoord > 1) {
      context_.warnings.push_back(where + " uses TEXCOORD_" + std::to_string(ref.texCoord) +
                                  ", but only TEXCOORD_0 and TEXCOORD_1 are loaded: using TEXCOORD_0");
      ref.texCoord = 0;
    }
    return ref;
  }

  int texture(int textureIndex, bool srgb, const std::string& where) {
    const tinygltf::Model& model = context_.model;
    if (static_cast<size_t>(textureIndex) >= model.textures.size())
      throw InvalidAsset(where + ": texture " + std::to_string(textureIndex) + " does not exist (the file has " +
                         std::to_string(model.textures.size()) + ")");
    const auto key = std::make_pair(textureIndex, srgb);
    if (const auto it = textures_.find(key); it != textures_.end()) return it->second;

    const tinygltf::Texture& in = model.textures[static_cast<size_t>(textureIndex)];
    const std::string name = describe("texture", static_cast<size_t>(textureIndex), in.name);
    if (in.source < 0)
      throw InvalidAsset(where + ": " + name +
                         " has no image source (textures only given by extensions such as KHR_texture_basisu are not "
                         "supported)");
    if (static_cast<size_t>(in.source) >= model.images.size())
      throw InvalidAsset(name + ": image " + std::to_string(in.source) + " does not exist (the file has " +
                         std::to_string(model.images.size()) + ")");
    if (in.sampler >= 0 && static_cast<size_t>(in.sampler) >= model.samplers.size())
      throw InvalidAsset(name + ": sampler " + std::to_string(in.sampler) + " does not exist (the file has " +
                         std::to_string(model.samplers.size()) + ")");

    const tinygltf::Image& image = model.images[static_cast<size_t>(in.source)];
    const DecodedImage& decoded = decode(in.source, where);
    Texture out;
    out.name = !in.name.empty() ? in.name : !image.name.empty() ? image.name : image.uri.starts_with("data:") ? "" : image.uri;
    if (out.name.empty()) out.name = name;
    out.width = decoded.width;
    out.height = decoded.height;
    out.pixels = decoded.rgba;
    out.srgb = srgb;
    out.sampler = in.sampler >= 0 ? in.sampler : defaultSampler();
    scene_.textures.push_back(std::move(out));
    const int index = static_cast<int>(scene_.textures.size() - 1);
    textures_.emplace(key, index);
    return index;
  }

  // Missing or undecodable images are errors here although tinygltf only
  // warns: a material without its texture would render wrong without a word.
  const DecodedImage& decode(int imageIndex, const std::string& where) {
    if (const auto it = images_.find(imageIndex); it != images_.end()) return it->second;
    const tinygltf::Image& image = context_.model.images[static_cast<size_t>(imageIndex)];
    std::string name = "image " + std::to_string(imageIndex);
    if (!image.uri.empty() && !image.uri.starts_with("data:")) name = "image '" + image.uri + "' (" + name + ")";
    else if (!image.name.empty()) name += " '" + image.name + "'";
    if (image.image.empty())
      throw InvalidAsset(name + ", used by " + where + ", is missing or unreadable");
    try {
      return images_.emplace(imageIndex, decodeImage(image.image, !context_.options.decodeImages)).first->second;
    } catch (const std::runtime_error& error) {
      throw InvalidAsset(name + ", used by " + where + ", cannot be decoded: " + error.what());
    }
  }

  int defaultSampler() {
    if (defaultSampler_ < 0) {
      scene_.samplers.push_back(Sampler{});
      defaultSampler_ = static_cast<int>(scene_.samplers.size() - 1);
    }
    return defaultSampler_;
  }

  const GltfContext& context_;
  Scene& scene_;
  std::map<std::pair<int, bool>, int> textures_;
  std::map<int, DecodedImage> images_;
  int defaultSampler_ = -1;
};

AlphaMode toAlphaMode(const std::string& mode) {
  if (mode == "MASK") return AlphaMode::Mask;
  if (mode == "BLEND") return AlphaMode::Blend;
  return AlphaMode::Opaque;  // "OPAQUE"; other values were rejected by the JSON check
}

// KHR_materials_emissive_strength: a finite factor >= 0 on the emissive colour (default 1).
float emissiveStrength(const tinygltf::Material& in, const std::string& name) {
  const auto it = in.extensions.find("KHR_materials_emissive_strength");
  if (it == in.extensions.end() || !it->second.IsObject() || !it->second.Has("emissiveStrength")) return 1.0f;
  const tinygltf::Value& value = it->second.Get("emissiveStrength");
  const double strength = value.IsNumber() ? value.GetNumberAsDouble() : -1.0;
  if (!(strength >= 0.0 && strength <= 3.0e38))
    throw InvalidAsset(name + ": KHR_materials_emissive_strength.emissiveStrength must be a finite number >= 0");
  return static_cast<float>(strength);
}

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// A material extension's number: `fallback` when absent, else finite and within [low, high].
float extensionNumber(const tinygltf::Value& extension, const char* key, float fallback, double low, double high,
                      const std::string& where) {
  if (!extension.Has(key)) return fallback;
  const tinygltf::Value& value = extension.Get(key);
  const double number = value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
  if (!(number >= low && number <= high))
    throw InvalidAsset(where + "." + key + " must be " +
                       (low < -1e30 ? std::string("a finite number")
                        : high > 1e30 ? "a finite number >= " + shortNumber(low)
                                      : "a number from " + shortNumber(low) + " to " + shortNumber(high)));
  return static_cast<float>(number);
}

glm::vec3 extensionColor(const tinygltf::Value& extension, const char* key, glm::vec3 fallback, double high,
                         const std::string& where) {
  if (!extension.Has(key)) return fallback;
  const tinygltf::Value& value = extension.Get(key);
  if (!value.IsArray() || value.ArrayLen() != 3) throw InvalidAsset(where + "." + key + " must be an array of 3 numbers");
  glm::vec3 out;
  for (int i = 0; i < 3; ++i) {
    const tinygltf::Value& component = value.Get(i);
    const double number = component.IsNumber() ? component.GetNumberAsDouble() : std::nan("");
    if (!(number >= 0.0 && number <= high))
      throw InvalidAsset(where + "." + key + "[" + std::to_string(i) + "] must be a number >= 0" +
                         (high < 1e30 ? " and <= 1" : ""));
    out[i] = static_cast<float>(number);
  }
  return out;
}

// The material extensions the layer stacks shade (materials/khr): each read
// into its Material member, textures included.
void convertLayerExtensions(const tinygltf::Material& in, const std::string& name, TextureBuilder& textures,
                            Material& out) {
  constexpr double kFinite = 3.0e38;
  const auto extension = [&](const char* key) -> const tinygltf::Value* {
    const auto it = in.extensions.find(key);
    if (it == in.extensions.end()) return nullptr;
    if (!it->second.IsObject()) throw InvalidAsset(name + ": " + key + " must be an object");
    return &it->second;
  };
  if (const tinygltf::Value* e = extension("KHR_materials_ior"))
    out.ior = extensionNumber(*e, "ior", 1.5f, 1.0, kFinite, name + ": KHR_materials_ior");
  if (const tinygltf::Value* e = extension("KHR_materials_specular")) {
    const std::string where = name + ": KHR_materials_specular";
    Specular specular;
    specular.factor = extensionNumber(*e, "specularFactor", 1.0f, 0.0, 1.0, where);
    specular.colorFactor = extensionColor(*e, "specularColorFactor", glm::vec3(1.0f), kFinite, where);
    specular.texture = textures.reference(e->Get("specularTexture"), false, where + ".specularTexture");
    specular.colorTexture = textures.reference(e->Get("specularColorTexture"), true, where + ".specularColorTexture");
    out.specular = specular;
  }
  if (const tinygltf::Value* e = extension("KHR_materials_sheen")) {
    const std::string where = name + ": KHR_materials_sheen";
    Sheen sheen;
    sheen.colorFactor = extensionColor(*e, "sheenColorFactor", glm::vec3(0.0f), 1.0, where);
    sheen.roughnessFactor = extensionNumber(*e, "sheenRoughnessFactor", 0.0f, 0.0, 1.0, where);
    sheen.colorTexture = textures.reference(e->Get("sheenColorTexture"), true, where + ".sheenColorTexture");
    sheen.roughnessTexture = textures.reference(e->Get("sheenRoughnessTexture"), false, where + ".sheenRoughnessTexture");
    out.sheen = sheen;
  }
  if (const tinygltf::Value* e = extension("KHR_materials_clearcoat")) {
    const std::string where = name + ": KHR_materials_clearcoat";
    Clearcoat coat;
    coat.factor = extensionNumber(*e, "clearcoatFactor", 0.0f, 0.0, 1.0, where);
    coat.roughnessFactor = extensionNumber(*e, "clearcoatRoughnessFactor", 0.0f, 0.0, 1.0, where);
    coat.texture = textures.reference(e->Get("clearcoatTexture"), false, where + ".clearcoatTexture");
    coat.roughnessTexture = textures.reference(e->Get("clearcoatRoughnessTexture"), false, where + ".clearcoatRoughnessTexture");
    const tinygltf::Value& normal = e->Get("clearcoatNormalTexture");
    coat.normalTexture = textures.reference(normal, false, where + ".clearcoatNormalTexture");
    if (normal.IsObject()) coat.normalScale = extensionNumber(normal, "scale", 1.0f, -kFinite, kFinite, where + ".clearcoatNormalTexture");
    out.clearcoat = coat;
  }
}

}  // namespace

void convertMaterials(const GltfContext& context, Scene& scene) {
  TextureBuilder textures(context, scene);
  const tinygltf::Model& model = context.model;
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& in = model.materials[i];
    const std::string name = describe("material", i, in.name);
    const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
    Material out;
    out.name = in.name;
    out.baseColorFactor = factor<4>(pbr.baseColorFactor, 1.0f);
    out.metallicFactor = static_cast<float>(pbr.metallicFactor);
    out.roughnessFactor = static_cast<float>(pbr.roughnessFactor);
    out.emissiveFactor = factor<3>(in.emissiveFactor, 0.0f);
    out.baseColorTexture = textures.reference(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                              pbr.baseColorTexture.extensions, true, name + " baseColorTexture");
    out.metallicRoughnessTexture =
        textures.reference(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                           pbr.metallicRoughnessTexture.extensions, false, name + " metallicRoughnessTexture");
    out.normalTexture = textures.reference(in.normalTexture.index, in.normalTexture.texCoord,
                                           in.normalTexture.extensions, false, name + " normalTexture");
    out.normalScale = static_cast<float>(in.normalTexture.scale);
    out.occlusionTexture = textures.reference(in.occlusionTexture.index, in.occlusionTexture.texCoord,
                                              in.occlusionTexture.extensions, false, name + " occlusionTexture");
    out.occlusionStrength = static_cast<float>(in.occlusionTexture.strength);
    out.emissiveTexture = textures.reference(in.emissiveTexture.index, in.emissiveTexture.texCoord,
                                             in.emissiveTexture.extensions, true, name + " emissiveTexture");
    out.alphaMode = toAlphaMode(in.alphaMode);
    out.alphaCutoff = static_cast<float>(in.alphaCutoff);
    out.doubleSided = in.doubleSided;
    out.unlit = in.extensions.count("KHR_materials_unlit") != 0;
    out.emissiveStrength = emissiveStrength(in, name);
    convertLayerExtensions(in, name, textures, out);
    scene.materials.push_back(std::move(out));
  }
}

}  // namespace sg::scene::detail
