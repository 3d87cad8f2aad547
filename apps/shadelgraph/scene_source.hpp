#pragma once
// Loads the scene a command names: nothing = the built-in default scene,
// .gltf/.glb = one glTF file, .json = a scene file.
#include <string>

#include <vector>

#include <shadelgraph/scene/camera_path.hpp>
#include <shadelgraph/scene/scene.hpp>

namespace sg::app {

struct LoadedScene {
  scene::Scene scene;
  std::vector<scene::CameraPath> cameraPaths;  // from a scene file
};

LoadedScene loadSceneArgument(const std::string& path);
// "1280x720" -> width, height; throws CLI::ValidationError-like std::invalid_argument.
void parseSize(const std::string& text, uint32_t& width, uint32_t& height);

}  // namespace sg::app
