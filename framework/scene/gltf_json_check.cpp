#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/gltf_json_check.hpp>
#include <shadelgraph/scene/gltf_json_links.hpp>
#include <shadelgraph/scene/input_limits.hpp>

namespace sg::scene::detail {
namespace {

using Json = nlohmann::json;

// The subset of the glTF 2.0 JSON schema the loader depends on: types,
// required properties, enums and minimums. Paths are JSON pointers, as the
// Khronos glTF-Validator names them ("/meshes/0/primitives"). References
// between objects and byte ranges are checked next (gltf_json_links.cpp).
class ShapeChecker {
 public:
  void root(const Json& json) {
    if (!json.is_object()) fail("the document", "an object", json);
    property(json, "");
    requireObject(json, "asset", "", [&](const Json& asset, const std::string& path) {
      required(asset, "version", path, glTF2Version);
      optionalString(asset, "generator", path);
      optional(asset, "minVersion", path, glTF2Version);
    });
    optionalStringArray(json, "extensionsUsed", "");
    optionalStringArray(json, "extensionsRequired", "");
    optionalIndex(json, "scene", "");
    objects(json, "scenes", [&](const Json& scene, const std::string& path) { optionalIndexArray(scene, "nodes", path); });
    objects(json, "nodes", [&](const Json& node, const std::string& path) { this->node(node, path); });
    objects(json, "meshes", [&](const Json& mesh, const std::string& path) { this->mesh(mesh, path); });
    objects(json, "accessors", [&](const Json& accessor, const std::string& path) { this->accessor(accessor, path); });
    objects(json, "bufferViews", [&](const Json& view, const std::string& path) { bufferView(view, path); });
    objects(json, "buffers", [&](const Json& buffer, const std::string& path) {
      optionalString(buffer, "uri", path);
      requirePositive(buffer, "byteLength", path);
    });
    objects(json, "materials", [&](const Json& material, const std::string& path) { this->material(material, path); });
    objects(json, "textures", [&](const Json& texture, const std::string& path) {
      optionalIndex(texture, "sampler", path);
      optionalIndex(texture, "source", path);
    });
    objects(json, "images", [&](const Json& image, const std::string& path) {
      optionalString(image, "uri", path);
      optionalString(image, "mimeType", path);
      optionalIndex(image, "bufferView", path);
    });
    objects(json, "samplers", [&](const Json& sampler, const std::string& path) {
      // The schema allows any integer for these GL enums (forward compatibility):
      // unknown values get a warning where they are converted.
      optionalInt32(sampler, "magFilter", path);
      optionalInt32(sampler, "minFilter", path);
      optionalInt32(sampler, "wrapS", path);
      optionalInt32(sampler, "wrapT", path);
    });
    objects(json, "cameras", [&](const Json& camera, const std::string& path) { this->camera(camera, path); });
    objects(json, "skins", [&](const Json& skin, const std::string& path) {
      optionalIndex(skin, "inverseBindMatrices", path);
      optionalIndex(skin, "skeleton", path);
      optionalIndexArray(skin, "joints", path);
    });
    objects(json, "animations", [&](const Json& animation, const std::string& path) {
      objects(animation, "channels", [&](const Json& channel, const std::string& p) {
        requireIndex(channel, "sampler", p);
        optionalObject(channel, "target", p, [&](const Json& target, const std::string& tp) { optionalIndex(target, "node", tp); });
      }, path);
      objects(animation, "samplers", [&](const Json& sampler, const std::string& p) {
        requireIndex(sampler, "input", p);
        requireIndex(sampler, "output", p);
      }, path);
    });
    if (const Json* extensions = member(json, "extensions"))
      optionalObject(*extensions, "KHR_lights_punctual", "/extensions", [&](const Json& lights, const std::string& path) {
        objects(lights, "lights", [&](const Json& light, const std::string& lightPath) { this->light(light, lightPath); },
                path);
      });
  }

 private:
  using Visit = std::function<void(const Json&, const std::string&)>;

  [[noreturn]] static void fail(const std::string& path, const std::string& expected, const Json& got) {
    throw InvalidAsset((path.empty() ? "the document" : path) + ": expected " + expected + ", got " + describe(got));
  }

  static std::string describe(const Json& value) {
    switch (value.type()) {
      case Json::value_t::null: return "null";
      case Json::value_t::object: return "an object";
      case Json::value_t::array: return "an array";
      case Json::value_t::string: return "the string " + capText(value.dump(), 80);
      case Json::value_t::boolean: return value.dump();
      case Json::value_t::number_integer:
      case Json::value_t::number_unsigned:
      case Json::value_t::number_float: return "the number " + value.dump();
      default: return "an unexpected value";
    }
  }

  // A JSON pointer one level down ("~" and "/" escaped as RFC 6901 says);
  // keys come from the file (extension and attribute names), so are capped.
  static std::string join(const std::string& path, const std::string& key) {
    std::string escaped;
    for (const char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
    return path + "/" + capText(escaped, 64);
  }

  static const Json* member(const Json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  // JSON Schema counts 3.0 as an integer, but tinygltf 2.7 does not: it
  // rejects a required 3.0 and silently drops an optional one (a byteOffset
  // of 8.0 reads from 0). So integers must be written without a fraction.
  static bool isInteger(const Json& value) { return value.is_number_integer() || value.is_number_unsigned(); }
  static bool isIntegralFloat(const Json& value) {
    return value.is_number_float() && std::isfinite(value.get<double>()) && value.get<double>() == std::floor(value.get<double>());
  }

  // name, extensions (an object of objects), extras: on every glTF object.
  void property(const Json& object, const std::string& path) {
    optionalString(object, "name", path);
    if (const Json* extensions = member(object, "extensions")) {
      const std::string extensionsPath = join(path, "extensions");
      if (!extensions->is_object()) fail(extensionsPath, "an object", *extensions);
      for (const auto& [name, value] : extensions->items())
        if (!value.is_object()) fail(join(extensionsPath, name), "an object", value);
    }
  }

  void objects(const Json& parent, const char* key, const Visit& visit, const std::string& parentPath = "") {
    const Json* array = member(parent, key);
    if (!array) return;
    const std::string path = join(parentPath, key);
    if (!array->is_array()) fail(path, "an array", *array);
    for (size_t i = 0; i < array->size(); ++i) {
      const Json& element = (*array)[i];
      const std::string elementPath = path + "/" + std::to_string(i);
      if (!element.is_object()) fail(elementPath, "an object", element);
      property(element, elementPath);
      visit(element, elementPath);
    }
  }

  void requireObject(const Json& parent, const char* key, const std::string& path, const Visit& visit) {
    if (!member(parent, key)) throw InvalidAsset(join(path, key) + ": required property is missing");
    optionalObject(parent, key, path, visit);
  }

  void optionalObject(const Json& parent, const char* key, const std::string& path, const Visit& visit) {
    const Json* value = member(parent, key);
    if (!value) return;
    const std::string childPath = join(path, key);
    if (!value->is_object()) fail(childPath, "an object", *value);
    property(*value, childPath);
    visit(*value, childPath);
  }

  template <class Check>
  void optional(const Json& parent, const char* key, const std::string& path, Check check) {
    if (const Json* value = member(parent, key)) check(*value, join(path, key));
  }
  template <class Check>
  void required(const Json& parent, const char* key, const std::string& path, Check check) {
    const Json* value = member(parent, key);
    if (!value) throw InvalidAsset(join(path, key) + ": required property is missing");
    check(*value, join(path, key));
  }

  static void string(const Json& value, const std::string& path) {
    if (!value.is_string()) fail(path, "a string", value);
  }
  static void boolean(const Json& value, const std::string& path) {
    if (!value.is_boolean()) fail(path, "true or false", value);
  }
  // Every number the loader reads becomes a 32-bit float: 1e39 is finite
  // as a double and infinite after the conversion.
  static void number(const Json& value, const std::string& path) {
    if (!value.is_number()) fail(path, "a number", value);
    if (!(std::abs(value.get<double>()) <= kFloatMax)) fail(path, "a number within the range of a 32-bit float", value);
  }
  // glTF ids and counts: integers >= 0.
  static void uint(const Json& value, const std::string& path) {
    if (isIntegralFloat(value)) fail(path, "an integer >= 0 written without a fraction", value);
    if (!isInteger(value) || (value.type() == Json::value_t::number_integer && value.get<int64_t>() < 0))
      fail(path, "an integer >= 0", value);
  }
  // Values tinygltf keeps in an int (enums, texCoord, sparse offsets): 2^32 + 9729 would
  // become a valid 9729. Indices need no such check: they are compared with array sizes.
  static void int32(const Json& value, const std::string& path) {
    uint(value, path);
    if (value.get<uint64_t>() > INT32_MAX) fail(path, "an integer in [0, 2147483647]", value);
  }
  // Counts and byte lengths the schema requires to be >= 1 (VALUE_NOT_IN_RANGE).
  static void positive(const Json& value, const std::string& path) {
    uint(value, path);
    if (value.get<uint64_t>() == 0) fail(path, "an integer >= 1", value);
  }
  // Material factors the schema bounds to [0, 1]: outside it they change
  // what is drawn (a metallic of -1 or a base colour of 3 is no material).
  static void unitNumber(const Json& value, const std::string& path) {
    number(value, path);
    if (!(value.get<double>() >= 0.0 && value.get<double>() <= 1.0)) fail(path, "a number in [0, 1]", value);
  }
  static void nonNegativeNumber(const Json& value, const std::string& path) {
    number(value, path);
    if (!(value.get<double>() >= 0.0)) fail(path, "a number >= 0", value);
  }
  // "2.0", "2.1": a major version other than 2 is a format this loader does
  // not know (the validator's UNKNOWN_ASSET_MAJOR_VERSION); minVersion above
  // 2.0 asks for features it does not have.
  static void glTF2Version(const Json& value, const std::string& path) {
    string(value, path);
    const std::string text = value.get<std::string>();
    const size_t dot = text.find('.');
    const auto digits = [](std::string_view s) {
      return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (dot == std::string::npos || !digits(std::string_view(text).substr(0, dot)) ||
        !digits(std::string_view(text).substr(dot + 1)))
      fail(path, "a version written <major>.<minor>", value);
    const bool minimum = path.ends_with("minVersion");
    if (text.substr(0, dot) != "2" || (minimum && text != "2.0"))
      fail(path, minimum ? "2.0 (this loader reads glTF 2.0)" : "a glTF 2.x version (this loader reads glTF 2.0)",
           value);
  }
  static void numbers(const Json& value, const std::string& path, size_t count, void (*each)(const Json&, const std::string&) = number) {
    if (!value.is_array() || (count && value.size() != count))
      fail(path, count ? "an array of " + std::to_string(count) + " numbers" : "an array of numbers", value);
    for (size_t i = 0; i < value.size(); ++i) each(value[i], path + "/" + std::to_string(i));
  }

  void optionalString(const Json& o, const char* key, const std::string& path) { optional(o, key, path, string); }
  void requireString(const Json& o, const char* key, const std::string& path) { required(o, key, path, string); }
  void optionalBool(const Json& o, const char* key, const std::string& path) { optional(o, key, path, boolean); }
  void optionalNumber(const Json& o, const char* key, const std::string& path) { optional(o, key, path, number); }
  void requireNumber(const Json& o, const char* key, const std::string& path) { required(o, key, path, number); }
  void optionalIndex(const Json& o, const char* key, const std::string& path) { optional(o, key, path, uint); }
  void requireIndex(const Json& o, const char* key, const std::string& path) { required(o, key, path, uint); }
  void requireUint(const Json& o, const char* key, const std::string& path) { required(o, key, path, uint); }
  void optionalUint(const Json& o, const char* key, const std::string& path) { optional(o, key, path, uint); }
  void requirePositive(const Json& o, const char* key, const std::string& path) { required(o, key, path, positive); }
  void optionalInt32(const Json& o, const char* key, const std::string& path) { optional(o, key, path, int32); }
  void optionalNumbers(const Json& o, const char* key, const std::string& path, size_t count) {
    optional(o, key, path, [count](const Json& value, const std::string& p) { numbers(value, p, count); });
  }
  void optionalUnitNumber(const Json& o, const char* key, const std::string& path) { optional(o, key, path, unitNumber); }
  void optionalUnitNumbers(const Json& o, const char* key, const std::string& path, size_t count) {
    optional(o, key, path, [count](const Json& value, const std::string& p) { numbers(value, p, count, unitNumber); });
  }
  void optionalIndexArray(const Json& o, const char* key, const std::string& path) {
    optional(o, key, path, [](const Json& value, const std::string& p) {
      if (!value.is_array()) fail(p, "an array of indices", value);
      for (size_t i = 0; i < value.size(); ++i) uint(value[i], p + "/" + std::to_string(i));
    });
  }
  void optionalStringArray(const Json& o, const char* key, const std::string& path) {
    optional(o, key, path, [](const Json& value, const std::string& p) {
      if (!value.is_array()) fail(p, "an array of strings", value);
      for (size_t i = 0; i < value.size(); ++i) string(value[i], p + "/" + std::to_string(i));
    });
  }
  template <class T>
  static void oneOf(const Json& value, const std::string& path, std::initializer_list<T> allowed) {
    std::string list;
    for (const T& option : allowed) {
      if (value == option) return;
      list += (list.empty() ? "" : ", ") + Json(option).dump();
    }
    fail(path, "one of " + list, value);
  }
  void optionalEnum(const Json& o, const char* key, const std::string& path,
                    std::initializer_list<std::string> allowed) {
    optional(o, key, path, [allowed](const Json& value, const std::string& p) {
      string(value, p);
      oneOf(value, p, allowed);
    });
  }

  void node(const Json& node, const std::string& path) {
    optionalIndex(node, "camera", path);
    optionalIndex(node, "mesh", path);
    optionalIndex(node, "skin", path);
    optionalIndexArray(node, "children", path);
    optionalNumbers(node, "matrix", path, 16);
    optionalNumbers(node, "rotation", path, 4);
    optionalNumbers(node, "scale", path, 3);
    optionalNumbers(node, "translation", path, 3);
    optionalNumbers(node, "weights", path, 0);
    if (const Json* extensions = member(node, "extensions"))
      optionalObject(*extensions, "KHR_lights_punctual", join(path, "extensions"),
                     [&](const Json& light, const std::string& p) { requireIndex(light, "light", p); });
  }

  void mesh(const Json& mesh, const std::string& path) {
    const Json* primitives = member(mesh, "primitives");
    if (!primitives) throw InvalidAsset(path + "/primitives: required property is missing");
    if (!primitives->is_array()) fail(path + "/primitives", "an array", *primitives);
    objects(mesh, "primitives", [&](const Json& primitive, const std::string& p) {
      requireObject(primitive, "attributes", p, [&](const Json& attributes, const std::string& attributesPath) {
        for (const auto& [name, value] : attributes.items()) uint(value, join(attributesPath, name));
      });
      optionalIndex(primitive, "indices", p);
      optionalIndex(primitive, "material", p);
      optionalInt32(primitive, "mode", p);
      objects(primitive, "targets", [](const Json& target, const std::string& targetPath) {
        for (const auto& [name, value] : target.items()) uint(value, join(targetPath, name));
      }, p);
    }, path);
    optionalNumbers(mesh, "weights", path, 0);
  }

  void accessor(const Json& accessor, const std::string& path) {
    optionalIndex(accessor, "bufferView", path);
    optionalUint(accessor, "byteOffset", path);
    required(accessor, "componentType", path,
             [](const Json& v, const std::string& p) { oneOf(v, p, {5120, 5121, 5122, 5123, 5125, 5126}); });
    optionalBool(accessor, "normalized", path);
    requirePositive(accessor, "count", path);
    required(accessor, "type", path, [](const Json& v, const std::string& p) {
      string(v, p);
      oneOf<std::string>(v, p, {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"});
    });
    optionalNumbers(accessor, "max", path, 0);
    optionalNumbers(accessor, "min", path, 0);
    optionalObject(accessor, "sparse", path, [&](const Json& sparse, const std::string& p) {
      requirePositive(sparse, "count", p);
      optionalInt32(sparse, "count", p);
      requireObject(sparse, "indices", p, [&](const Json& indices, const std::string& ip) {
        requireIndex(indices, "bufferView", ip);
        optionalInt32(indices, "byteOffset", ip);
        required(indices, "componentType", ip, [](const Json& v, const std::string& cp) { oneOf(v, cp, {5121, 5123, 5125}); });
      });
      requireObject(sparse, "values", p, [&](const Json& values, const std::string& vp) {
        requireIndex(values, "bufferView", vp);
        optionalInt32(values, "byteOffset", vp);
      });
    });
  }

  void bufferView(const Json& view, const std::string& path) {
    requireIndex(view, "buffer", path);
    optionalUint(view, "byteOffset", path);
    requirePositive(view, "byteLength", path);
    optional(view, "byteStride", path, [](const Json& v, const std::string& p) {
      if (!isInteger(v) || v.get<double>() < 4.0 || v.get<double>() > 252.0 || v.get<int64_t>() % 4 != 0)
        fail(p, "a multiple of 4 in [4, 252]", v);
    });
    optionalInt32(view, "target", path);
  }

  void textureInfo(const Json& parent, const char* key, const std::string& path, const char* extraNumber = nullptr,
                   void (*extraCheck)(const Json&, const std::string&) = number) {
    optionalObject(parent, key, path, [&](const Json& info, const std::string& p) {
      requireIndex(info, "index", p);
      optionalInt32(info, "texCoord", p);
      if (extraNumber) optional(info, extraNumber, p, extraCheck);
      if (const Json* extensions = member(info, "extensions"))
        optionalObject(*extensions, "KHR_texture_transform", join(p, "extensions"),
                       [&](const Json& transform, const std::string& tp) {
                         optionalNumbers(transform, "offset", tp, 2);
                         optionalNumber(transform, "rotation", tp);
                         optionalNumbers(transform, "scale", tp, 2);
                         optionalInt32(transform, "texCoord", tp);
                       });
    });
  }

  void material(const Json& material, const std::string& path) {
    optionalObject(material, "pbrMetallicRoughness", path, [&](const Json& pbr, const std::string& p) {
      optionalUnitNumbers(pbr, "baseColorFactor", p, 4);
      textureInfo(pbr, "baseColorTexture", p);
      optionalUnitNumber(pbr, "metallicFactor", p);
      optionalUnitNumber(pbr, "roughnessFactor", p);
      textureInfo(pbr, "metallicRoughnessTexture", p);
    });
    textureInfo(material, "normalTexture", path, "scale");
    textureInfo(material, "occlusionTexture", path, "strength", unitNumber);
    textureInfo(material, "emissiveTexture", path);
    optionalUnitNumbers(material, "emissiveFactor", path, 3);
    optionalEnum(material, "alphaMode", path, {"OPAQUE", "MASK", "BLEND"});
    optional(material, "alphaCutoff", path, nonNegativeNumber);
    optionalBool(material, "doubleSided", path);
  }

  void camera(const Json& camera, const std::string& path) {
    optionalEnum(camera, "type", path, {"perspective", "orthographic"});
    requireString(camera, "type", path);
    optionalObject(camera, "perspective", path, [&](const Json& perspective, const std::string& p) {
      optionalNumber(perspective, "aspectRatio", p);
      requireNumber(perspective, "yfov", p);
      optionalNumber(perspective, "zfar", p);
      requireNumber(perspective, "znear", p);
    });
    optionalObject(camera, "orthographic", path, [&](const Json& orthographic, const std::string& p) {
      requireNumber(orthographic, "xmag", p);
      requireNumber(orthographic, "ymag", p);
      requireNumber(orthographic, "zfar", p);
      requireNumber(orthographic, "znear", p);
    });
  }

  void light(const Json& light, const std::string& path) {
    optionalEnum(light, "type", path, {"directional", "point", "spot"});
    requireString(light, "type", path);
    optionalNumbers(light, "color", path, 3);
    optionalNumber(light, "intensity", path);
    optionalNumber(light, "range", path);
    optionalObject(light, "spot", path, [&](const Json& spot, const std::string& p) {
      optionalNumber(spot, "innerConeAngle", p);
      optionalNumber(spot, "outerConeAngle", p);
    });
  }
};

}  // namespace

void checkGltfJson(std::string_view json, std::span<const std::string_view> supportedExtensions) {
  if (const auto error = jsonDepthError(json)) throw InvalidAsset(*error);
  Json document;
  try {
    document = Json::parse(json.begin(), json.end());
  } catch (const Json::exception& error) {  // parse_error, and out_of_range for numbers such as 1e999
    throw InvalidAsset("invalid JSON: " + capText(error.what()));
  }
  if (document.is_object())
    if (const auto required = document.find("extensionsRequired"); required != document.end() && required->is_array())
      for (const Json& name : *required)
        if (name.is_string() &&
            std::find(supportedExtensions.begin(), supportedExtensions.end(), name.get<std::string>()) ==
                supportedExtensions.end())
          throw InvalidAsset("requires the unsupported extension " + capText(name.get<std::string>(), 80));
  ShapeChecker().root(document);
  checkGltfLinks(document);
}

}  // namespace sg::scene::detail
