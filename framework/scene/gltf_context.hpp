#pragma once
// Internal to the glTF loader (not public API): state shared by its stages.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include <shadelgraph/scene/gltf_loader.hpp>

namespace sg::scene::detail {

// Thrown by the loader's stages with a message that names what is wrong;
// loadGltf prefixes the file name and rethrows it as SceneError.
class InvalidAsset : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct GltfContext {
  const tinygltf::Model& model;
  const LoadOptions& options;
  std::vector<std::string>& warnings;
};

// "mesh 2 'Wheel'" / "mesh 2": how messages name an object.
inline std::string describe(const char* kind, size_t index, const std::string& name) {
  std::string text = std::string(kind) + " " + std::to_string(index);
  if (!name.empty()) text += " '" + (name.size() <= 64 ? name : name.substr(0, 64) + "...") + "'";  // names may be huge
  return text;
}

}  // namespace sg::scene::detail
