#include "shadel_test_support.hpp"

#include <algorithm>
#include <random>

namespace sg::shadel::test {

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

scene::Mesh meshWithUvs(std::vector<glm::vec2> uvs, std::vector<uint32_t> indices) {
  scene::Primitive primitive;
  for (glm::vec2 uv : uvs) {
    primitive.positions.emplace_back(uv, 0.0f);
    primitive.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  primitive.uv0 = std::move(uvs);
  primitive.indices = std::move(indices);
  scene::Mesh mesh;
  mesh.name = "synthetic";
  mesh.primitives.push_back(std::move(primitive));
  return mesh;
}

TempDir::TempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "shadel_test";
  std::replace(name.begin(), name.end(), '/', '_');
  path_ = std::filesystem::temp_directory_path() / ("sg_shadel_" + name + "_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace sg::shadel::test
