#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include <shadelgraph/scene/gltf_accessor.hpp>
#include <shadelgraph/scene/gltf_context.hpp>
#include <shadelgraph/scene/gltf_json_check.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/gltf_material.hpp>
#include <shadelgraph/scene/gltf_mesh.hpp>
#include <shadelgraph/scene/gltf_nodes.hpp>

namespace sg::scene {
namespace {

using detail::InvalidAsset;

constexpr std::string_view kSupportedExtensions[] = {"KHR_texture_transform", "KHR_lights_punctual",
                                                     "KHR_materials_unlit"};

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

// A .glb's JSON chunk; empty when the container is malformed (tinygltf then
// reports what is wrong with it).
std::string_view glbJson(const std::vector<uint8_t>& bytes) {
  if (bytes.size() < 20) return {};
  uint32_t length = 0, type = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  std::memcpy(&type, bytes.data() + 16, 4);
  if (type != 0x4E4F534Au || length > bytes.size() - 20) return {};
  return {reinterpret_cast<const char*>(bytes.data() + 20), length};
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
  if (!json.empty()) detail::checkGltfJson(json, kSupportedExtensions);

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
  if (!ok || !error.empty()) throw InvalidAsset(error.empty() ? "tinygltf could not parse the file" : oneLine(error));

  Scene scene;
  if (!warning.empty()) scene.warnings.push_back(oneLine(warning));
  warnUnsupportedExtensions(model, scene.warnings);
  detail::checkBufferViews(model);
  const detail::GltfContext context{model, options, scene.warnings};
  detail::convertMaterials(context, scene);
  detail::convertMeshes(context, scene);
  detail::convertNodes(context, scene);
  return scene;
}

}  // namespace

Scene loadGltf(const std::filesystem::path& file, const LoadOptions& options) {
  try {
    return load(file, options);
  } catch (const InvalidAsset& error) {
    throw SceneError(file, error.what());
  } catch (const std::bad_alloc&) {
    throw SceneError(file, "out of memory (is a count in the file absurdly large?)");
  } catch (const std::length_error& error) {
    throw SceneError(file, std::string("a size in the file is too large: ") + error.what());
  }
}

}  // namespace sg::scene
