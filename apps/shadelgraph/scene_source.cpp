#include "scene_source.hpp"

#include <filesystem>
#include <stdexcept>

#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/scene_file.hpp>

namespace sg::app {

LoadedScene loadSceneArgument(const std::string& path) {
  if (path.empty()) return {scene::makeDefaultScene(), {}};
  const auto ext = std::filesystem::path(path).extension();
  if (ext == ".gltf" || ext == ".glb") return {scene::loadGltf(path), {}};
  if (ext == ".json") {
    auto file = scene::loadSceneFile(path);
    return {std::move(file.scene), std::move(file.cameraPaths)};
  }
  throw std::invalid_argument(path + ": unknown scene type (expected .gltf, .glb or .json)");
}

}  // namespace sg::app
