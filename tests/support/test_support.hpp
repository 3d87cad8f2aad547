#pragma once
// What every test folder shares: where the sample models are, and a
// temporary directory that cleans up after itself.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

namespace sg::test {

// The Khronos sample models (../shared/assets/gltf beside the project).
std::filesystem::path assetsDir();
bool haveAssets();
// <assets>/<model>/glTF/<model>.gltf
std::filesystem::path samplePath(std::string_view model);
// Every sample model's .gltf, sorted by name.
std::vector<std::filesystem::path> allSamples();

// Debian's assimp-testmodels.
std::filesystem::path assimpDir();
bool haveAssimpModels();

// A fresh directory named after the running test, removed with its contents
// when this goes away.
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

}  // namespace sg::test

// Skips (with the reason) a test that needs the sample models when they are absent.
#define SG_REQUIRE_ASSETS()                                                                                 \
  do {                                                                                                      \
    if (!::sg::test::haveAssets())                                                                          \
      GTEST_SKIP() << "glTF sample assets not found at " << ::sg::test::assetsDir()                         \
                   << " (../shared/assets/gltf beside the project)";                                        \
  } while (false)
