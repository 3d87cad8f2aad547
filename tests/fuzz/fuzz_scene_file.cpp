// libFuzzer target: the scene-file loader (sg::scene::loadSceneFile). The
// scene file is written next to links to the glTF seed models, so objects
// the seeds name ("Box.gltf", "Triangle.glb", ...) load; its contract is
// SceneError for any bad file, as for fuzz_gltf.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include <shadelgraph/scene/scene_file.hpp>

#include "fuzz_scratch.hpp"

namespace {

// Once per process: every model of the glTF seed corpus, linked into the scratch directory.
bool linkModels() {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(SG_FUZZ_MODELS_DIR, error))
    std::filesystem::create_symlink(entry.path(), sg::fuzz::scratchDir() / entry.path().filename(), error);
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const bool linked = linkModels();
  (void)linked;
  const auto path = sg::fuzz::writeInput("scene.json", data, size);
  try {
    const sg::scene::SceneFile file = sg::scene::loadSceneFile(path);
    volatile size_t sink = sg::scene::instancedTriangleCount(file.scene) + file.cameraPaths.size();
    (void)sink;
  } catch (const sg::scene::SceneError&) {
  }
  return 0;
}
