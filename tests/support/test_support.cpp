#include "test_support.hpp"

#include <algorithm>
#include <fstream>
#include <random>

#include <unistd.h>

namespace sg::test {

std::filesystem::path assetsDir() { return std::filesystem::path(SG_ASSETS_DIR).lexically_normal(); }

bool haveAssets() { return std::filesystem::is_directory(assetsDir()); }

std::filesystem::path samplePath(std::string_view model) {
  return assetsDir() / model / "glTF" / (std::string(model) + ".gltf");
}

std::vector<std::filesystem::path> allSamples() {
  std::vector<std::filesystem::path> files;
  if (!haveAssets()) return files;
  for (const auto& entry : std::filesystem::directory_iterator(assetsDir())) {
    const std::filesystem::path file = samplePath(entry.path().filename().string());
    if (std::filesystem::exists(file)) files.push_back(file);
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::filesystem::path assimpDir() { return "/usr/share/assimp/models/glTF2"; }

bool haveAssimpModels() { return std::filesystem::is_directory(assimpDir()); }

TempDir::TempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "test";
  std::replace(name.begin(), name.end(), '/', '_');
  path_ = std::filesystem::temp_directory_path() /
          ("sg_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path TempDir::write(const std::string& name, std::string_view text) const {
  const std::filesystem::path file = path_ / name;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
  return file;
}

std::filesystem::path TempDir::write(const std::string& name, const std::vector<uint8_t>& bytes) const {
  return write(name, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

}  // namespace sg::test
