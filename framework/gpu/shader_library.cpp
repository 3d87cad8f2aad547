#include <shadelgraph/gpu/shader_library.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace sg::gpu {

void ShaderLibrary::add(std::span<const EmbeddedShaderFile> files) {
  for (const auto& f : files) files_[f.path] = f.source;
}

void ShaderLibrary::add(std::string path, std::string source) { files_[std::move(path)] = std::move(source); }

void ShaderLibrary::addDirectory(std::filesystem::path directory) {
  // Every renderer adds its plugins' directories; once is enough.
  if (std::find(directories_.begin(), directories_.end(), directory) == directories_.end())
    directories_.push_back(std::move(directory));
}

std::optional<std::filesystem::path> ShaderLibrary::fileOf(const std::string& path) const {
  if (files_.count(path)) return std::nullopt;
  for (const auto& dir : directories_)
    if (std::filesystem::is_regular_file(dir / path)) return dir / path;
  return std::nullopt;
}

std::optional<std::string> ShaderLibrary::find(const std::string& path) const {
  if (auto it = files_.find(path); it != files_.end()) return it->second;
  for (const auto& dir : directories_) {
    std::ifstream in(dir / path, std::ios::binary);
    if (!in) continue;
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }
  return std::nullopt;
}

}  // namespace sg::gpu
