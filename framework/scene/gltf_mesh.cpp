#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>

#include <shadelgraph/scene/closed_surface.hpp>
#include <shadelgraph/scene/gltf_accessor.hpp>
#include <shadelgraph/scene/gltf_mesh.hpp>
#include <shadelgraph/scene/input_limits.hpp>
#include <shadelgraph/scene/mesh_order.hpp>
#include <shadelgraph/scene/normals.hpp>
#include <shadelgraph/scene/tangents.hpp>
#include <shadelgraph/scene/triangulate.hpp>

namespace sg::scene::detail {
namespace {

// Which accessor formats an attribute accepts (glTF 2.0 core, without
// KHR_mesh_quantization).
struct AttributeFormat {
  std::initializer_list<int> components;
  bool normalizedUnsigned = false;  // also normalized UNSIGNED_BYTE / UNSIGNED_SHORT
};

std::string expected(const AttributeFormat& format) {
  std::string types;
  for (int components : format.components) types += std::string(types.empty() ? "" : " or ") + typeName(components);
  return types + (format.normalizedUnsigned ? " of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT" : " of FLOAT");
}

template <int N>
std::string toText(const glm::vec<N, float>& v) {
  std::ostringstream out;
  out << "(";
  for (int i = 0; i < N; ++i) out << (i ? ", " : "") << v[i];
  out << ")";
  return out.str();
}

class PrimitiveBuilder {
 public:
  PrimitiveBuilder(const GltfContext& context, Scene& scene, int& defaultMaterial)
      : context_(context), scene_(scene), defaultMaterial_(defaultMaterial) {
    // Every accessor is read once per primitive that uses it, so thousands of
    // primitives sharing one large accessor would multiply the file's bytes:
    // reads are capped at 8x the buffers' bytes plus 64 MiB.
    uint64_t bufferBytes = 0;
    for (const tinygltf::Buffer& buffer : context.model.buffers) bufferBytes += buffer.data.size();
    readBudget_ = 8 * bufferBytes + (uint64_t{64} << 20);
  }

  // nullopt: the primitive is skipped (with a warning).
  std::optional<Primitive> build(const tinygltf::Primitive& in, const std::string& where) {
    where_ = where;
    in_ = &in;
    const int mode = in.mode < 0 ? TINYGLTF_MODE_TRIANGLES : in.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP ||
        mode == TINYGLTF_MODE_LINE_STRIP) {
      context_.warnings.push_back(where + ": " + (mode == TINYGLTF_MODE_POINTS ? "points" : "lines") +
                                  " are not rendered; skipped");
      return std::nullopt;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      context_.warnings.push_back(where + ": unknown mode " + std::to_string(mode) + "; skipped");
      return std::nullopt;
    }
    if (!in.attributes.contains("POSITION")) {
      context_.warnings.push_back(where + ": has no POSITION; skipped");
      return std::nullopt;
    }

    Primitive out;
    out.positions = attribute<3>("POSITION", {{3}}, std::nullopt);
    const size_t vertexCount = out.positions.size();
    out.normals = attribute<3>("NORMAL", {{3}}, vertexCount);
    out.tangents = attribute<4>("TANGENT", {{4}}, vertexCount);
    out.uv0 = attribute<2>("TEXCOORD_0", {{2}, true}, vertexCount);
    out.uv1 = attribute<2>("TEXCOORD_1", {{2}, true}, vertexCount);
    out.colors = colors(vertexCount);
    out.indices = triangleList(mode, vertexCount);
    out.material = material();
    skinAttributes(out);
    out.targets = morphTargets(vertexCount);

    if (out.normals.empty()) {
      out.tangents.clear();  // glTF: tangents without normals must be ignored
      generateFlatNormals(out);
      repairs_["no NORMAL, flat normals generated"].push_back(where);
    } else {
      normalize(out.normals);
    }
    if (!out.tangents.empty()) {
      normalize(out.tangents);
    } else if (const TextureRef normalMap = tangentSpaceMap(scene_.materials[static_cast<size_t>(out.material)]);
               normalMap.present()) {
      if (!out.uvs(normalMap.texCoord).empty()) {
        addTangents(out, normalMap.texCoord);
        repairs_["normal map without TANGENT, MikkTSpace tangents generated"].push_back(where);
      }
    }
    warnMissingTexCoords(out);
    for (const glm::vec3& p : out.positions) out.bounds.extend(p);
    out.closedSurface = isClosedSurface(out.positions, out.indices);
    return out;
  }

  // The normal map tangents are generated for: the base's, else the clear coat's (KHR_materials_clearcoat).
  static TextureRef tangentSpaceMap(const Material& material) {
    if (material.normalTexture.present() || !material.clearcoat) return material.normalTexture;
    return material.clearcoat->normalTexture;
  }

  // One warning per kind of repair, not one per primitive.
  void reportRepairs() {
    if (!minMaxMismatches_.empty())
      context_.warnings.push_back("accessor min/max differ from the data (ignored: bounds are computed): " +
                                  minMaxMismatches_.front() +
                                  (minMaxMismatches_.size() > 1 ? " and " + std::to_string(minMaxMismatches_.size() - 1) + " more" : ""));
    for (const auto& [what, primitives] : repairs_)
      context_.warnings.push_back(what + ": " + primitives.front() +
                                  (primitives.size() > 1 ? " and " + std::to_string(primitives.size() - 1) + " more" : ""));
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InvalidAsset(where_ + ": " + what); }

  // Charged before reading: counts were checked against the bytes behind
  // them (unbacked ones bounded), so count x element size cannot overflow.
  PackedAccessor read(int index, const std::string& what) {
    if (index >= 0 && static_cast<size_t>(index) < context_.model.accessors.size()) {
      const tinygltf::Accessor& accessor = context_.model.accessors[static_cast<size_t>(index)];
      const int elementSize = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(accessor.componentType)) *
                              tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
      bytesRead_ += accessor.count * static_cast<uint64_t>(std::clamp(elementSize, 1, 64));
    }
    if (bytesRead_ > readBudget_)
      fail("the primitives would read " + std::to_string(bytesRead_) + " bytes of accessors, more than 8 times the " +
           "file's buffers plus 64 MiB (" + std::to_string(readBudget_) + "): is one accessor shared by thousands of primitives?");
    return readAccessor(context_.model, index, what);
  }

  void warnMissingTexCoords(const Primitive& primitive) {
    const Material& material = scene_.materials[static_cast<size_t>(primitive.material)];
    const std::pair<const char*, const TextureRef*> refs[] = {
        {"baseColorTexture", &material.baseColorTexture}, {"metallicRoughnessTexture", &material.metallicRoughnessTexture},
        {"normalTexture", &material.normalTexture},       {"occlusionTexture", &material.occlusionTexture},
        {"emissiveTexture", &material.emissiveTexture}};
    for (const auto& [slot, ref] : refs)
      if (ref->present() && primitive.uvs(ref->texCoord).empty())
        context_.warnings.push_back(where_ + ": its material's " + slot + " uses TEXCOORD_" +
                                    std::to_string(ref->texCoord) + ", which the primitive lacks");
  }

  // The attribute's elements as vectors, or empty when absent. Every
  // attribute but POSITION (vertexCount nullopt) must match POSITION's count.
  template <int N>
  std::vector<glm::vec<N, float>> attribute(const char* name, const AttributeFormat& format,
                                            std::optional<size_t> vertexCount) {
    return attributeIn<N>(in_->attributes, name, format, vertexCount);
  }

  // JOINTS_0/WEIGHTS_0 and, when the file has them, JOINTS_1/WEIGHTS_1; a
  // vertex's weights are normalized to sum 1 (glTF asks writers for that).
  void skinAttributes(Primitive& out) {
    const size_t vertexCount = out.positions.size();
    for (int set = 0; set < 3; ++set) {
      const std::string joints = "JOINTS_" + std::to_string(set), weights = "WEIGHTS_" + std::to_string(set);
      const bool hasJoints = in_->attributes.contains(joints), hasWeights = in_->attributes.contains(weights);
      if (!hasJoints && !hasWeights) break;
      if (hasJoints != hasWeights) fail(joints + " and " + weights + " must come together");
      if (set == 2) {
        context_.warnings.push_back(where_ + ": influences beyond JOINTS_1/WEIGHTS_1 (8 per vertex) are ignored");
        break;
      }
      const int index = in_->attributes.at(joints);
      const PackedAccessor accessor = read(index, where_ + " " + joints);
      if (accessor.components != 4 || accessor.normalized ||
          (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
           accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
        fail(joints + " (accessor " + std::to_string(index) + ") is " + typeName(accessor.components) + " of " +
             componentTypeName(accessor.componentType) + "; expected VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT");
      if (accessor.count != vertexCount)
        fail(joints + " has " + std::to_string(accessor.count) + " elements, POSITION has " + std::to_string(vertexCount));
      const std::vector<uint32_t> values = toUints(accessor);
      std::vector<glm::uvec4>& outJoints = set == 0 ? out.joints0 : out.joints1;
      outJoints.resize(vertexCount);
      for (size_t v = 0; v < vertexCount; ++v)
        outJoints[v] = glm::uvec4(values[4 * v], values[4 * v + 1], values[4 * v + 2], values[4 * v + 3]);
      (set == 0 ? out.weights0 : out.weights1) = attribute<4>(weights.c_str(), {{4}, true}, vertexCount);
    }
    size_t repaired = 0;
    for (size_t v = 0; v < out.weights0.size(); ++v) {
      glm::vec4& w0 = out.weights0[v];
      glm::vec4 zero(0.0f);
      glm::vec4& w1 = out.weights1.empty() ? zero : out.weights1[v];
      if (glm::any(glm::lessThan(w0, zero)) || glm::any(glm::lessThan(w1, zero)))
        fail("WEIGHTS of vertex " + std::to_string(v) + " are negative");
      const float total = w0.x + w0.y + w0.z + w0.w + w1.x + w1.y + w1.z + w1.w;
      if (total > 0.0f) {
        repaired += std::abs(total - 1.0f) > 2e-3f;
        w0 /= total;
        w1 /= total;
      }
    }
    if (repaired)
      context_.warnings.push_back(where_ + ": " + std::to_string(repaired) + " vertices' WEIGHTS did not sum to 1; normalized");
  }

  // POSITION, NORMAL and TANGENT deltas of each morph target (others are not applied).
  std::vector<MorphTarget> morphTargets(size_t vertexCount) {
    std::vector<MorphTarget> out;
    for (size_t t = 0; t < in_->targets.size(); ++t) {
      const std::map<std::string, int>& attributes = in_->targets[t];
      MorphTarget& target = out.emplace_back();
      const std::string prefix = "target " + std::to_string(t) + " ";
      target.positions = attributeIn<3>(attributes, "POSITION", {{3}}, vertexCount, prefix);
      target.normals = attributeIn<3>(attributes, "NORMAL", {{3}}, vertexCount, prefix);
      target.tangents = attributeIn<3>(attributes, "TANGENT", {{3}}, vertexCount, prefix);
      for (const auto& [name, accessor] : attributes)
        if (name != "POSITION" && name != "NORMAL" && name != "TANGENT")
          repairs_["morph target " + name + " deltas are not applied"].push_back(where_);
    }
    return out;
  }

  template <int N>
  std::vector<glm::vec<N, float>> attributeIn(const std::map<std::string, int>& attributes, const char* name,
                                              const AttributeFormat& format, std::optional<size_t> vertexCount,
                                              const std::string& prefix = {}) {
    const auto it = attributes.find(name);
    if (it == attributes.end()) return {};
    const std::string what = where_ + " " + prefix + name;
    const PackedAccessor accessor = read(it->second, what);
    checkFormat(accessor, format, (prefix + name).c_str(), it->second);
    if (vertexCount && accessor.count != *vertexCount)
      fail(prefix + name + " has " + std::to_string(accessor.count) + " elements, POSITION has " +
           std::to_string(*vertexCount));
    const std::vector<float> floats = toFloats(accessor);
    std::vector<glm::vec<N, float>> out(accessor.count);
    const bool position = std::string_view(name) == "POSITION";  // deltas too: their sums must stay finite
    for (size_t i = 0; i < accessor.count; ++i) {
      for (int c = 0; c < N; ++c) out[i][c] = floats[i * N + static_cast<size_t>(c)];
      for (int c = 0; c < N; ++c) {
        if (!std::isfinite(out[i][c])) fail(prefix + name + " " + std::to_string(i) + " is not finite: " + toText(out[i]));
        if (position && static_cast<double>(std::abs(out[i][c])) > kMaxCoordinate)
          fail(prefix + "POSITION " + std::to_string(i) + " " + toText(out[i]) +
               " is beyond +-1e18, where squared lengths overflow 32-bit float");
      }
    }
    checkMinMax(context_.model.accessors[static_cast<size_t>(it->second)], floats, N, it->second);
    return out;
  }

  // ACCESSOR_MIN_MISMATCH / ACCESSOR_MAX_MISMATCH: a warning, not an error.
  // The loader computes bounds from the data and never reads min/max, so a
  // wrong declaration changes nothing that is drawn.
  void checkMinMax(const tinygltf::Accessor& accessor, const std::vector<float>& floats, int components, int index) {
    const auto n = static_cast<size_t>(components);
    if (floats.empty() || accessor.normalized) return;  // normalized: min/max are in the stored integers
    for (const auto& [declared, isMax] : {std::pair{&accessor.minValues, false}, std::pair{&accessor.maxValues, true}}) {
      if (declared->size() != n) continue;
      for (size_t c = 0; c < n; ++c) {
        float actual = floats[c];
        for (size_t i = c; i < floats.size(); i += n) actual = isMax ? std::max(actual, floats[i]) : std::min(actual, floats[i]);
        const auto stated = static_cast<float>((*declared)[c]);
        if (std::abs(actual - stated) > 1e-5f * std::max(1.0f, std::abs(actual))) {
          minMaxMismatches_.push_back("/accessors/" + std::to_string(index) + "/" + (isMax ? "max/" : "min/") +
                                      std::to_string(c));
          break;
        }
      }
    }
  }

  void checkFormat(const PackedAccessor& accessor, const AttributeFormat& format, const char* name, int index) const {
    bool componentsOk = false;
    for (int components : format.components) componentsOk |= accessor.components == components;
    const bool typeOk = accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                        (format.normalizedUnsigned && accessor.normalized &&
                         (accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                          accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
    if (!componentsOk || !typeOk)
      fail(std::string(name) + " (accessor " + std::to_string(index) + ") is " + typeName(accessor.components) + " of " +
           (accessor.normalized ? "normalized " : "") + componentTypeName(accessor.componentType) + "; expected " +
           expected(format));
  }

  std::vector<glm::vec4> colors(size_t vertexCount) {
    const auto it = in_->attributes.find("COLOR_0");
    if (it == in_->attributes.end()) return {};
    const PackedAccessor accessor = read(it->second, where_ + " COLOR_0");
    checkFormat(accessor, {{3, 4}, true}, "COLOR_0", it->second);
    if (accessor.count != vertexCount)
      fail("COLOR_0 has " + std::to_string(accessor.count) + " elements, POSITION has " + std::to_string(vertexCount));
    const std::vector<float> floats = toFloats(accessor);
    const auto n = static_cast<size_t>(accessor.components);
    std::vector<glm::vec4> out(accessor.count, glm::vec4(1.0f));
    for (size_t i = 0; i < accessor.count; ++i)
      for (size_t c = 0; c < n; ++c) {
        out[i][static_cast<int>(c)] = floats[i * n + c];
        if (!std::isfinite(floats[i * n + c])) fail("COLOR_0 " + std::to_string(i) + " is not finite");
      }
    return out;
  }

  std::vector<uint32_t> triangleList(int mode, size_t vertexCount) {
    std::vector<uint32_t> corners;
    if (in_->indices >= 0) {
      const PackedAccessor accessor = read(in_->indices, where_ + " indices");
      const int type = accessor.componentType;
      if (accessor.components != 1 ||
          (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
           type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail("indices (accessor " + std::to_string(in_->indices) + ") are " + typeName(accessor.components) + " of " +
             componentTypeName(type) + "; expected SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
      corners = toUints(accessor);
      for (size_t i = 0; i < corners.size(); ++i)
        if (corners[i] >= vertexCount)
          fail("index " + std::to_string(corners[i]) + " (indices[" + std::to_string(i) +
               "]) is out of range: the primitive has " + std::to_string(vertexCount) + " vertices (/accessors/" +
               std::to_string(in_->indices) + ", ACCESSOR_INDEX_OOB)");
    } else {
      corners.resize(vertexCount);
      std::iota(corners.begin(), corners.end(), 0u);
    }
    const Topology topology = mode == TINYGLTF_MODE_TRIANGLE_STRIP ? Topology::TriangleStrip
                              : mode == TINYGLTF_MODE_TRIANGLE_FAN ? Topology::TriangleFan
                                                                   : Topology::TriangleList;
    if (topology == Topology::TriangleList && corners.size() % 3 != 0)
      context_.warnings.push_back(where_ + ": " + std::to_string(corners.size()) +
                                  " corners is not a multiple of 3; the last " + std::to_string(corners.size() % 3) +
                                  " are ignored");
    return toTriangleList(corners, topology);
  }

  int material() {
    if (in_->material < 0) {
      if (defaultMaterial_ < 0) {
        Material fallback;  // glTF's default: white, metallic 1, roughness 1, no textures
        fallback.name = "default";
        scene_.materials.push_back(fallback);
        defaultMaterial_ = static_cast<int>(scene_.materials.size() - 1);
      }
      return defaultMaterial_;
    }
    if (static_cast<size_t>(in_->material) >= context_.model.materials.size())
      fail("material " + std::to_string(in_->material) + " does not exist (the file has " +
           std::to_string(context_.model.materials.size()) + ")");
    return in_->material;
  }

  // Zero or non-finite normals cannot be repaired meaningfully: error. Others
  // are renormalized, with a warning when far from unit length.
  void normalize(std::vector<glm::vec3>& normals) {
    size_t repaired = 0;
    for (size_t i = 0; i < normals.size(); ++i) {
      const float length = glm::length(normals[i]);
      if (!(length > 1e-6f)) fail("NORMAL " + std::to_string(i) + " has zero length: " + toText(normals[i]));
      if (std::abs(length - 1.0f) > 1e-2f) ++repaired;
      normals[i] /= length;
    }
    if (repaired)
      context_.warnings.push_back(where_ + ": " + std::to_string(repaired) + " NORMALs were not unit length; renormalized");
  }

  // Tangents are only used with a normal map, so bad ones are repaired.
  void normalize(std::vector<glm::vec4>& tangents) {
    size_t repaired = 0;
    for (glm::vec4& tangent : tangents) {
      const glm::vec3 xyz{tangent};
      const float length = glm::length(xyz);
      const float w = tangent.w < 0.0f ? -1.0f : 1.0f;
      if (std::abs(length - 1.0f) > 1e-2f || std::abs(tangent.w) != 1.0f) ++repaired;
      tangent = length > 1e-6f ? glm::vec4(xyz / length, w) : glm::vec4(1.0f, 0.0f, 0.0f, w);
    }
    if (repaired)
      context_.warnings.push_back(where_ + ": " + std::to_string(repaired) + " TANGENTs were not unit length with w = +-1; repaired");
  }

  const GltfContext& context_;
  Scene& scene_;
  int& defaultMaterial_;
  const tinygltf::Primitive* in_ = nullptr;
  std::string where_;
  std::map<std::string, std::vector<std::string>> repairs_;
  std::vector<std::string> minMaxMismatches_;
  uint64_t bytesRead_ = 0;
  uint64_t readBudget_ = 0;
};

}  // namespace

namespace {

// The mesh's default morph weights: the file's, else 0 per target. glTF asks
// every primitive of a mesh for the same number of targets.
std::vector<float> morphWeights(const tinygltf::Mesh& in, const Mesh& mesh, const std::string& name) {
  size_t targets = 0;
  for (const Primitive& primitive : mesh.primitives) {
    if (targets && primitive.morphed() && primitive.targets.size() != targets)
      throw InvalidAsset(name + ": its primitives have different numbers of morph targets");
    targets = std::max(targets, primitive.targets.size());
  }
  if (in.weights.empty()) return std::vector<float>(targets, 0.0f);
  if (in.weights.size() != targets)
    throw InvalidAsset(name + ": " + std::to_string(in.weights.size()) + " weights for " + std::to_string(targets) +
                       " morph targets");
  std::vector<float> out;
  for (double w : in.weights) {
    if (!std::isfinite(w)) throw InvalidAsset(name + ": a morph weight is not finite");
    out.push_back(static_cast<float>(w));
  }
  return out;
}

}  // namespace

void convertMeshes(const GltfContext& context, Scene& scene) {
  int defaultMaterial = -1;
  PrimitiveBuilder builder(context, scene, defaultMaterial);
  const tinygltf::Model& model = context.model;
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    const tinygltf::Mesh& in = model.meshes[m];
    Mesh out;
    out.name = in.name;
    const std::string name = describe("mesh", m, in.name);
    for (size_t p = 0; p < in.primitives.size(); ++p) {
      std::optional<Primitive> primitive = builder.build(in.primitives[p], name + " primitive " + std::to_string(p));
      if (!primitive) continue;
      // Last: tangents and flat normals above were generated in the file's order.
      const MeshOrderOptions& order = context.options.meshOrder;
      if (order.any() && mayReorder(*primitive, scene.materials[static_cast<size_t>(primitive->material)]))
        orderForRendering(*primitive, order);
      out.bounds.extend(primitive->bounds);
      out.primitives.push_back(std::move(*primitive));
    }
    out.weights = morphWeights(in, out, name);
    scene.meshes.push_back(std::move(out));
  }
  builder.reportRepairs();
}

}  // namespace sg::scene::detail
