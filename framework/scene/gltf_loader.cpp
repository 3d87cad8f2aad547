#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include <shadelgraph/scene/gltf_accessor.hpp>
#include <shadelgraph/scene/gltf_animation.hpp>
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/gltf_json_check.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/gltf_skin.hpp>
#include <shadelgraph/scene/gltf_material.hpp>
#include <shadelgraph/scene/gltf_mesh.hpp>
#include <shadelgraph/scene/gltf_nodes.hpp>
#include <shadelgraph/scene/input_limits.hpp>

namespace sg::scene {
namespace {

using detail::capText;
using detail::InvalidAsset;

// What a file may require (extensionsRequired); anything else is refused by name.
constexpr std::string_view kSupportedExtensions[] = {
    "KHR_texture_transform",   "KHR_lights_punctual",   "KHR_materials_unlit",    "KHR_materials_emissive_strength",
    "KHR_materials_clearcoat", "KHR_materials_sheen",   "KHR_materials_specular", "KHR_materials_ior"};

std::vector<uint8_t> readFile(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) throw InvalidAsset("no such file");
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InvalidAsset("cannot open the file");
  std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  if (stream.bad()) throw InvalidAsset("cannot read the file");
  return bytes;
}

bool isGlb(const std::vector<uint8_t>& bytes) { return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0; }

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t offset) {
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4);
  return value;
}

// A .glb's JSON chunk, after checking the container as the glTF-Validator
// does (tinygltf 2.7 accepts a wrong version, a header length that differs
// from the file's and chunks that overrun or do not tile the file).
std::string_view glbJson(const std::vector<uint8_t>& bytes) {
  constexpr uint32_t kJson = 0x4E4F534Au, kBin = 0x004E4942u;
  if (bytes.size() < 12) throw InvalidAsset("GLB: " + std::to_string(bytes.size()) + "-byte file is shorter than the 12-byte header (GLB_UNEXPECTED_END_OF_HEADER)");
  if (const uint32_t version = readU32(bytes, 4); version != 2)
    throw InvalidAsset("GLB: header version " + std::to_string(version) + ", expected 2 (GLB_INVALID_VERSION)");
  if (const uint32_t length = readU32(bytes, 8); length != bytes.size())
    throw InvalidAsset("GLB: header length " + std::to_string(length) + " differs from the file's " +
                       std::to_string(bytes.size()) + " bytes (GLB_LENGTH_MISMATCH)");
  std::string_view json;
  size_t offset = 12;
  for (int chunk = 0; offset < bytes.size(); ++chunk) {
    const std::string name = "GLB chunk " + std::to_string(chunk);
    if (bytes.size() - offset < 8)
      throw InvalidAsset(name + ": " + std::to_string(bytes.size() - offset) + " bytes left for an 8-byte chunk header (GLB_UNEXPECTED_END_OF_CHUNK_HEADER)");
    const uint32_t length = readU32(bytes, offset), type = readU32(bytes, offset + 4);
    offset += 8;
    if (length > bytes.size() - offset)
      throw InvalidAsset(name + ": length " + std::to_string(length) + " runs past the end of the file (" +
                         std::to_string(bytes.size() - offset) + " bytes left) (GLB_CHUNK_TOO_BIG)");
    if (length % 4 != 0)
      throw InvalidAsset(name + ": length " + std::to_string(length) + " is not a multiple of 4 (GLB_CHUNK_LENGTH_UNALIGNED)");
    if (chunk == 0 && type != kJson) throw InvalidAsset(name + ": the first chunk must be JSON (GLB_UNEXPECTED_FIRST_CHUNK)");
    if (chunk > 0 && type == kJson) throw InvalidAsset(name + ": a second JSON chunk (GLB_DUPLICATE_CHUNK)");
    if (chunk > 1 && type == kBin) throw InvalidAsset(name + ": a BIN chunk must directly follow the JSON chunk (GLB_UNEXPECTED_BIN_CHUNK)");
    if (chunk == 0) json = {reinterpret_cast<const char*>(bytes.data() + offset), length};
    offset += length;
  }
  if (json.empty()) throw InvalidAsset("GLB: no JSON content (GLB_UNEXPECTED_END_OF_HEADER)");
  return json;
}

// Image loader for tinygltf that keeps the encoded bytes: decoding happens
// later, only for images a material uses, with errors that name the material.
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->image.assign(bytes, bytes + size);
  image->as_is = true;
  return true;
}

// tinygltf's multi-line text as one line.
std::string oneLine(const std::string& text) {
  std::string line;
  std::istringstream lines(text);
  for (std::string part; std::getline(lines, part);) {
    part.erase(part.find_last_not_of(" \t\r") + 1);
    if (!part.empty()) line += (line.empty() ? "" : "; ") + part;
  }
  return line;
}

// Required ones were checked with the JSON; the others are only used for
// optional features, which are ignored.
void warnUnsupportedExtensions(const tinygltf::Model& model, std::vector<std::string>& warnings) {
  std::string ignored;
  for (const std::string& used : model.extensionsUsed)
    if (std::find(std::begin(kSupportedExtensions), std::end(kSupportedExtensions), used) == std::end(kSupportedExtensions))
      ignored += (ignored.empty() ? "" : ", ") + used;
  if (!ignored.empty()) warnings.push_back("ignoring unsupported extensions: " + ignored);
}

Scene load(const std::filesystem::path& file, const LoadOptions& options) {
  const std::vector<uint8_t> bytes = readFile(file);
  if (bytes.size() > UINT32_MAX) throw InvalidAsset("files over 4 GiB are not supported");
  const bool binary = isGlb(bytes);
  const std::string_view json =
      binary ? glbJson(bytes) : std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  detail::checkGltfJson(json, kSupportedExtensions);

  tinygltf::TinyGLTF parser;
  parser.SetImageLoader(keepEncodedImage, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const std::string baseDir = file.parent_path().string();
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? parser.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), size, baseDir)
                         : parser.LoadASCIIFromString(&model, &error, &warning,
                                                      reinterpret_cast<const char*>(bytes.data()), size, baseDir);
  // tinygltf can report an error and still return true (e.g. a texture info without "index").
  if (!ok || !error.empty()) throw InvalidAsset(error.empty() ? "tinygltf could not parse the file" : capText(oneLine(error), 400));

  Scene scene;
  if (!warning.empty()) scene.warnings.push_back(oneLine(warning));
  warnUnsupportedExtensions(model, scene.warnings);
  detail::checkBufferViews(model);
  const detail::GltfContext context{model, options, scene.warnings};
  detail::convertMaterials(context, scene);
  detail::convertMeshes(context, scene);
  const std::vector<int> sceneNodeOf = detail::convertNodes(context, scene);
  detail::convertSkins(context, sceneNodeOf, scene);
  detail::convertAnimations(context, sceneNodeOf, scene);
  detail::capWarnings(scene.warnings);
  return scene;
}

}  // namespace

Scene loadGltf(const std::filesystem::path& file, const LoadOptions& options) {
  try {
    return load(file, options);
  } catch (const InvalidAsset& error) {
    throw SceneError(file, detail::capText(error.what(), 1000));
  } catch (const std::bad_alloc&) {
    throw SceneError(file, "out of memory (is a count in the file absurdly large?)");
  } catch (const std::length_error& error) {
    throw SceneError(file, std::string("a size in the file is too large: ") + error.what());
  }
}

}  // namespace sg::scene
