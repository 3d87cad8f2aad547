#pragma once
// Shared helpers for the shadel tests: the sample models, small synthetic
// meshes, a temporary directory.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::shadel::test {

// The Khronos sample models (shared/assets/gltf beside the project).
std::filesystem::path assetsDir();
bool haveAssets();
// <assets>/<model>/glTF/<model>.gltf
std::filesystem::path samplePath(std::string_view model);
// Every sample model's .gltf, sorted by name.
std::vector<std::filesystem::path> allSamples();

// One primitive with TEXCOORD_0 = uvs and positions (u, v, 0).
scene::Mesh meshWithUvs(std::vector<glm::vec2> uvs, std::vector<uint32_t> indices);

// A fresh directory, removed with its contents when this goes away.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace sg::shadel::test

#define SG_SHADEL_REQUIRE_ASSETS()                                                                                \
  do {                                                                                                            \
    if (!::sg::shadel::test::haveAssets())                                                                        \
      GTEST_SKIP() << "glTF sample assets not found at " << ::sg::shadel::test::assetsDir()                       \
                   << " (they live in shared/assets/gltf beside the project)";                                    \
  } while (0)
