#include "scene_source.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/scene_file.hpp>

namespace sg::app {
namespace {

// SG_MESH_ORDER: "off" loads glTF triangles in the file's order; a list of
// "cache", "overdraw", "fetch" enables just those steps (mesh_order.hpp).
// Unset: the defaults (cache, overdraw). For A/B measurements of one binary.
scene::LoadOptions loadOptions() {
  scene::LoadOptions options;
  const char* value = std::getenv("SG_MESH_ORDER");
  if (!value || !*value) return options;
  const std::string steps = value;
  if (steps != "off" && steps.find_first_not_of("cacheoverdrwfth,") != std::string::npos)
    throw std::invalid_argument(std::string("SG_MESH_ORDER=") + value + ": expected off, or some of cache,overdraw,fetch");
  options.meshOrder.vertexCache = steps.find("cache") != std::string::npos;
  if (steps.find("overdraw") == std::string::npos) options.meshOrder.overdrawThreshold = 0.0f;
  options.meshOrder.vertexFetch = steps.find("fetch") != std::string::npos;
  return options;
}

}  // namespace

LoadedScene loadSceneArgument(const std::string& path) {
  if (path.empty()) return {scene::makeDefaultScene(), {}};
  const auto ext = std::filesystem::path(path).extension();
  if (ext == ".gltf" || ext == ".glb") return {scene::loadGltf(path, loadOptions()), {}};
  if (ext == ".json") {
    auto file = scene::loadSceneFile(path, loadOptions());
    return {std::move(file.scene), std::move(file.cameraPaths)};
  }
  throw std::invalid_argument(path + ": unknown scene type (expected .gltf, .glb or .json)");
}

}  // namespace sg::app
