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

void parseSize(const std::string& text, uint32_t& width, uint32_t& height) {
  unsigned w = 0, h = 0;
  char x = 0;
  if (std::sscanf(text.c_str(), "%u%c%u", &w, &x, &h) != 3 || (x != 'x' && x != 'X') || w == 0 || h == 0 ||
      w > 16384 || h > 16384)
    throw std::invalid_argument("--size '" + text + "': expected WIDTHxHEIGHT, e.g. 1280x720 (at most 16384 each)");
  width = w;
  height = h;
}

}  // namespace sg::app
