#pragma once
// Shared helpers for the scene tests: where the test models are, and a
// temporary directory to write synthesized glTF files into.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

namespace sg::scene::test {

// The Khronos sample models (see shared/assets/README.md).
std::filesystem::path assetsDir();
bool haveAssets();
// <assets>/<model>/glTF/<model>.gltf
std::filesystem::path samplePath(std::string_view model);

// Debian's assimp-testmodels.
std::filesystem::path assimpDir();
bool haveAssimpModels();

// A fresh directory, removed with everything in it when this goes away.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& name, std::string_view text) const;
  std::filesystem::path write(const std::string& name, const std::vector<uint8_t>& bytes) const;

 private:
  std::filesystem::path path_;
};

// Little-endian bytes of floats / 16-bit / 32-bit values, to build .bin files.
std::vector<uint8_t> bytesOf(const std::vector<float>& values);
std::vector<uint8_t> bytesOf(const std::vector<uint16_t>& values);
std::vector<uint8_t> bytesOf(const std::vector<uint32_t>& values);
std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts);

// A glTF with one triangle mesh (36 bytes of POSITION in "triangle.bin") and
// whatever `nodes` / `extra` JSON the test adds: `nodes` is the nodes array's
// content, `extra` more top-level members (with a leading comma).
std::filesystem::path writeTriangleGltf(const TempDir& dir, const std::string& name, const std::string& nodes,
                                        const std::string& sceneNodes, const std::string& extra = "");

}  // namespace sg::scene::test

#define SG_REQUIRE_ASSETS()                                                                                     \
  do {                                                                                                          \
    if (!::sg::scene::test::haveAssets())                                                                       \
      GTEST_SKIP() << "glTF sample assets not found at " << ::sg::scene::test::assetsDir()                      \
                   << " (they live in shared/assets/gltf beside the project)";                                  \
  } while (0)

#define SG_REQUIRE_ASSIMP_MODELS()                                                                              \
  do {                                                                                                          \
    if (!::sg::scene::test::haveAssimpModels())                                                                 \
      GTEST_SKIP() << "assimp test models not found at " << ::sg::scene::test::assimpDir()                      \
                   << " (apt-get install assimp-testmodels)";                                                   \
  } while (0)
