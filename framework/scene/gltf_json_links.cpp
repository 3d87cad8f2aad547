#include <cctype>
#include <cmath>
#include <string>

#include <shadelgraph/scene/checked_math.hpp>
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/gltf_json_links.hpp>
#include <shadelgraph/scene/input_limits.hpp>

namespace sg::scene::detail {
namespace {

using Json = nlohmann::json;

const Json* member(const Json& object, const char* key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

uint64_t uintOr(const Json& object, const char* key, uint64_t fallback) {
  const Json* value = member(object, key);
  return value ? value->get<uint64_t>() : fallback;
}

const Json& arrayOrEmpty(const Json& object, const char* key) {
  static const Json empty = Json::array();
  const Json* value = member(object, key);
  return value && value->is_array() ? *value : empty;
}

std::string at(const std::string& path, size_t index) { return path + "/" + std::to_string(index); }

size_t componentSize(uint64_t componentType) {
  switch (componentType) {
    case 5120:
    case 5121: return 1;
    case 5122:
    case 5123: return 2;
    default: return 4;  // 5125, 5126; others were rejected by the shape check
  }
}

// Bytes of one element, with the column padding glTF requires for matrices
// of 1- and 2-byte components.
uint64_t elementSize(const Json& accessor) {
  const std::string type = accessor["type"].get<std::string>();
  const uint64_t size = componentSize(accessor["componentType"].get<uint64_t>());
  if (type == "SCALAR") return size;
  if (type == "VEC2") return 2 * size;
  if (type == "VEC3") return 3 * size;
  if (type == "VEC4") return 4 * size;
  const uint64_t columns = type == "MAT2" ? 2 : type == "MAT3" ? 3 : 4;
  const uint64_t column = (columns * size + 3) / 4 * 4;
  return columns * column;
}

// A data: URI tinygltf can decode: base64, and only base64 characters after
// the comma. tinygltf's own error quotes the whole URI (68 KB lines).
void checkDataUri(const Json& holder, const std::string& path) {
  const Json* uri = member(holder, "uri");
  if (!uri || !uri->is_string()) return;
  const std::string& text = uri->get_ref<const std::string&>();
  if (!text.starts_with("data:")) return;
  const size_t comma = text.find(',');
  const bool base64 = comma != std::string::npos && comma >= 7 && text.compare(comma - 7, 7, ";base64") == 0;
  size_t bad = std::string::npos;
  if (base64)
    for (size_t i = comma + 1; i < text.size() && bad == std::string::npos; ++i)
      if (!std::isalnum(static_cast<unsigned char>(text[i])) && text[i] != '+' && text[i] != '/' && text[i] != '=') bad = i;
  if (!base64 || bad != std::string::npos)
    throw InvalidAsset(path + "/uri: " + (base64 ? "data: URI has a non-base64 character at " + std::to_string(bad)
                                                 : std::string("data: URI is not base64")) +
                       " (" + capText(text, 48) + ")");
}

class LinkChecker {
 public:
  explicit LinkChecker(const Json& root) : root_(root) {
    if (const Json* extensions = member(root, "extensions"))
      if (const Json* lights = member(*extensions, "KHR_lights_punctual")) lights_ = &arrayOrEmpty(*lights, "lights");
  }

  void run() {
    reference(member(root_, "scene"), "/scene", "scenes");
    each("scenes", [&](const Json& scene, const std::string& path) { references(scene, "nodes", path, "nodes"); });
    each("nodes", [&](const Json& node, const std::string& path) { this->node(node, path); });
    each("meshes", [&](const Json& mesh, const std::string& path) { this->mesh(mesh, path); });
    each("bufferViews", [&](const Json& view, const std::string& path) { bufferView(view, path); });
    each("accessors", [&](const Json& accessor, const std::string& path) { this->accessor(accessor, path); });
    each("textures", [&](const Json& texture, const std::string& path) {
      reference(texture, "sampler", path, "samplers");
      reference(texture, "source", path, "images");
    });
    each("images", [&](const Json& image, const std::string& path) {
      reference(image, "bufferView", path, "bufferViews");
      checkDataUri(image, path);
    });
    each("buffers", [&](const Json& buffer, const std::string& path) { checkDataUri(buffer, path); });
    each("materials", [&](const Json& material, const std::string& path) { this->material(material, path); });
    each("skins", [&](const Json& skin, const std::string& path) {
      reference(skin, "inverseBindMatrices", path, "accessors");
      reference(skin, "skeleton", path, "nodes");
      references(skin, "joints", path, "nodes");
    });
    each("animations", [&](const Json& animation, const std::string& path) {
      const uint64_t samplers = arrayOrEmpty(animation, "samplers").size();
      const Json& channels = arrayOrEmpty(animation, "channels");
      for (size_t c = 0; c < channels.size(); ++c) {
        const std::string channelPath = at(path + "/channels", c);
        check(member(channels[c], "sampler"), channelPath + "/sampler", "animation sampler", samplers);
        if (const Json* target = member(channels[c], "target")) reference(*target, "node", channelPath + "/target", "nodes");
      }
      const Json& samplerList = arrayOrEmpty(animation, "samplers");
      for (size_t s = 0; s < samplerList.size(); ++s) {
        reference(samplerList[s], "input", at(path + "/samplers", s), "accessors");
        reference(samplerList[s], "output", at(path + "/samplers", s), "accessors");
      }
    });
  }

 private:
  template <class Visit>
  void each(const char* key, Visit visit) {
    const Json& array = arrayOrEmpty(root_, key);
    for (size_t i = 0; i < array.size(); ++i) visit(array[i], at(std::string("/") + key, i));
  }

  uint64_t size(const char* what) const {
    if (std::string_view(what) == "lights") return lights_ ? lights_->size() : 0;
    return arrayOrEmpty(root_, what).size();
  }

  // UNRESOLVED_REFERENCE, against the raw value: tinygltf would cut 2^32 to 0.
  static void check(const Json* value, const std::string& path, const std::string& what, uint64_t count) {
    if (!value) return;
    const uint64_t index = value->get<uint64_t>();
    if (index >= count)
      throw InvalidAsset(path + ": " + what + " " + std::to_string(index) + " does not exist (the file has " +
                         std::to_string(count) + ")");
  }
  void reference(const Json* value, const std::string& path, const char* target) {
    const std::string_view plural(target);
    const std::string_view singular = plural == "meshes" ? "mesh" : plural.substr(0, plural.size() - 1);
    check(value, path, std::string(singular), size(target));
  }
  void reference(const Json& object, const char* key, const std::string& path, const char* target) {
    reference(member(object, key), path + "/" + key, target);
  }
  void references(const Json& object, const char* key, const std::string& path, const char* target) {
    const Json& list = arrayOrEmpty(object, key);
    for (size_t i = 0; i < list.size(); ++i) reference(&list[i], at(path + "/" + key, i), target);
  }

  void node(const Json& node, const std::string& path) {
    reference(node, "camera", path, "cameras");
    reference(node, "mesh", path, "meshes");
    reference(node, "skin", path, "skins");
    references(node, "children", path, "nodes");
    if (const Json* extensions = member(node, "extensions"))
      if (const Json* light = member(*extensions, "KHR_lights_punctual"))
        reference(*light, "light", path + "/extensions/KHR_lights_punctual", "lights");
    if (const Json* translation = member(node, "translation"))
      for (size_t i = 0; i < translation->size(); ++i) coordinate((*translation)[i], at(path + "/translation", i));
    if (const Json* matrix = member(node, "matrix")) {
      if (member(node, "translation") || member(node, "rotation") || member(node, "scale"))
        throw InvalidAsset(path + ": has both a matrix and translation/rotation/scale (NODE_MATRIX_TRS)");
      checkTrs(*matrix, path + "/matrix");
      for (size_t i = 12; i < 15; ++i) coordinate((*matrix)[i], at(path + "/matrix", i));
    }
  }

  static void coordinate(const Json& value, const std::string& path) {
    if (std::abs(value.get<double>()) > kMaxCoordinate)
      throw InvalidAsset(path + ": " + value.dump() + " is beyond +-1e18, where squared lengths overflow 32-bit float");
  }

  // NODE_MATRIX_NON_TRS: the last row is (0, 0, 0, 1) and the columns of
  // the upper 3x3 are orthogonal (a rotation times a scale), or the node
  // could not be animated or decomposed as glTF requires.
  static void checkTrs(const Json& matrix, const std::string& path) {
    double m[16];
    for (size_t i = 0; i < 16; ++i) m[i] = matrix[i].get<double>();
    const bool lastRow = m[3] == 0.0 && m[7] == 0.0 && m[11] == 0.0 && m[15] == 1.0;
    bool orthogonal = true;
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const double* u = m + 4 * a;
        const double* v = m + 4 * b;
        const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        const double lv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (lu == 0.0 || lv == 0.0) continue;  // a zero scale hides the rotation; still TRS
        if (std::abs((u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / (lu * lv)) > 1e-4) orthogonal = false;
      }
    if (!lastRow || !orthogonal)
      throw InvalidAsset(path + ": is not decomposable to translation, rotation and scale (NODE_MATRIX_NON_TRS: " +
                         (lastRow ? "sheared" : "last row is not 0, 0, 0, 1") + ")");
  }

  void mesh(const Json& mesh, const std::string& path) {
    const Json& primitives = arrayOrEmpty(mesh, "primitives");
    for (size_t p = 0; p < primitives.size(); ++p) {
      const std::string primitivePath = at(path + "/primitives", p);
      const Json& primitive = primitives[p];
      if (const Json* attributes = member(primitive, "attributes"))
        for (const auto& [name, value] : attributes->items())
          reference(&value, primitivePath + "/attributes/" + capText(name, 40), "accessors");
      reference(primitive, "indices", primitivePath, "accessors");
      reference(primitive, "material", primitivePath, "materials");
      const Json& targets = arrayOrEmpty(primitive, "targets");
      for (size_t t = 0; t < targets.size(); ++t)
        for (const auto& [name, value] : targets[t].items())
          reference(&value, at(primitivePath + "/targets", t) + "/" + capText(name, 40), "accessors");
    }
  }

  void bufferView(const Json& view, const std::string& path) {
    reference(view, "buffer", path, "buffers");
    const Json& buffer = arrayOrEmpty(root_, "buffers")[view["buffer"].get<size_t>()];
    const uint64_t bufferLength = buffer["byteLength"].get<uint64_t>();
    const uint64_t offset = uintOr(view, "byteOffset", 0);
    const uint64_t length = view["byteLength"].get<uint64_t>();
    if (!fitsIn(offset, length, bufferLength))
      throw InvalidAsset(path + ": bytes at offset " + std::to_string(offset) + ", length " + std::to_string(length) +
                         " do not fit buffer " + std::to_string(view["buffer"].get<uint64_t>()) + "'s byteLength " +
                         std::to_string(bufferLength) + " (BUFFER_VIEW_TOO_LONG)");
  }

  const Json& view(const Json& holder, const std::string& path) {
    reference(holder, "bufferView", path, "bufferViews");
    return arrayOrEmpty(root_, "bufferViews")[holder["bufferView"].get<size_t>()];
  }

  // `count` elements `stride` apart from `offset` inside the bufferView.
  static void fits(const Json& view, uint64_t offset, uint64_t count, uint64_t elementBytes, uint64_t stride,
                   const std::string& path) {
    const uint64_t viewLength = view["byteLength"].get<uint64_t>();
    if (offset > viewLength)
      throw InvalidAsset(path + "/byteOffset: " + std::to_string(offset) + " is past the end of its bufferView (" +
                         std::to_string(viewLength) + " bytes) (ACCESSOR_TOO_LONG)");
    const std::optional<uint64_t> end = elementsEnd(offset, count, elementBytes, stride);
    if (!end || *end > viewLength)
      throw InvalidAsset(path + ": " + std::to_string(count) + " elements of " + std::to_string(elementBytes) +
                         " bytes" + (stride != elementBytes ? ", " + std::to_string(stride) + " apart," : "") +
                         " from offset " + std::to_string(offset) + " do not fit its bufferView's " +
                         std::to_string(viewLength) + " bytes (ACCESSOR_TOO_LONG)");
  }

  void accessor(const Json& accessor, const std::string& path) {
    const uint64_t count = accessor["count"].get<uint64_t>();
    const uint64_t bytes = elementSize(accessor);
    if (member(accessor, "bufferView")) {
      const Json& bufferView = view(accessor, path);
      const uint64_t stride = uintOr(bufferView, "byteStride", bytes);
      if (stride < bytes)
        throw InvalidAsset(path + ": its bufferView's byteStride " + std::to_string(stride) + " is smaller than its " +
                           std::to_string(bytes) + "-byte elements (ACCESSOR_SMALL_BYTESTRIDE)");
      fits(bufferView, uintOr(accessor, "byteOffset", 0), count, bytes, stride, path);
    } else if (count > kMaxUnbackedAccessorElements) {
      throw InvalidAsset(path + "/count: " + std::to_string(count) +
                         " elements without a bufferView (at most " + std::to_string(kMaxUnbackedAccessorElements) +
                         ": no bytes in the file back them)");
    }
    const Json* sparse = member(accessor, "sparse");
    if (!sparse) return;
    const std::string sparsePath = path + "/sparse";
    const uint64_t sparseCount = (*sparse)["count"].get<uint64_t>();
    if (sparseCount > count)
      throw InvalidAsset(sparsePath + "/count: " + std::to_string(sparseCount) + " exceeds the accessor's count " +
                         std::to_string(count) + " (ACCESSOR_SPARSE_COUNT_OUT_OF_RANGE)");
    const Json& indices = (*sparse)["indices"];
    const uint64_t indexBytes = componentSize(indices["componentType"].get<uint64_t>());
    fits(view(indices, sparsePath + "/indices"), uintOr(indices, "byteOffset", 0), sparseCount, indexBytes, indexBytes,
         sparsePath + "/indices");
    const Json& values = (*sparse)["values"];
    fits(view(values, sparsePath + "/values"), uintOr(values, "byteOffset", 0), sparseCount, bytes, bytes,
         sparsePath + "/values");
  }

  void textureInfo(const Json& parent, const char* key, const std::string& path) {
    const Json* info = member(parent, key);
    if (!info) return;
    const std::string infoPath = path + "/" + key;
    reference(*info, "index", infoPath, "textures");
    const Json* extensions = member(*info, "extensions");
    const Json* transform = extensions ? member(*extensions, "KHR_texture_transform") : nullptr;
    if (!transform) return;
    const std::string transformPath = infoPath + "/extensions/KHR_texture_transform";
    for (const char* vector : {"offset", "scale"})
      if (const Json* values = member(*transform, vector))
        for (size_t i = 0; i < values->size(); ++i) coordinate((*values)[i], at(transformPath + "/" + vector, i));
  }

  void material(const Json& material, const std::string& path) {
    if (const Json* pbr = member(material, "pbrMetallicRoughness")) {
      textureInfo(*pbr, "baseColorTexture", path + "/pbrMetallicRoughness");
      textureInfo(*pbr, "metallicRoughnessTexture", path + "/pbrMetallicRoughness");
    }
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) textureInfo(material, key, path);
  }

  const Json& root_;
  const Json* lights_ = nullptr;
};

}  // namespace

void checkGltfLinks(const nlohmann::json& document) { LinkChecker(document).run(); }

}  // namespace sg::scene::detail
