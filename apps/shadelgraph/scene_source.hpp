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

}  // namespace sg::app
