#pragma once
// Where GLSL sources come from, by virtual path ("passes/tonemap/tonemap.comp"):
// sources embedded in the binary at build time (cmake/ShaderEmbedding.cmake),
// in-memory sources added at run time (generated material variants, tests),
// and directories on disk (a plugin's shader folder, or a live-edit override).
#include <filesystem>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sg::gpu {

struct EmbeddedShaderFile {
  const char* path;
  const char* source;
};

class ShaderLibrary {
 public:
  void add(std::span<const EmbeddedShaderFile> files);
  void add(std::string path, std::string source);
  void addDirectory(std::filesystem::path directory);
  // The source at a virtual path: in-memory first, then the directories.
  std::optional<std::string> find(const std::string& path) const;
  // Where on disk `find` reads the path from; nullopt for in-memory sources.
  std::optional<std::filesystem::path> fileOf(const std::string& path) const;

 private:
  std::map<std::string, std::string> files_;
  std::vector<std::filesystem::path> directories_;
};

}  // namespace sg::gpu
