#pragma once
// GLSL -> SPIR-V at run time through glslang, with #include resolved against a
// ShaderLibrary, #defines, and an on-disk cache keyed by a hash of the
// preprocessed source and the options (so editing an included file misses).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <shadelgraph/gpu/shader_library.hpp>

namespace sg::gpu {

enum class ShaderStage { Vertex, Fragment, Compute };

struct ShaderRequest {
  std::string path;  // virtual path; also the name in error messages
  std::string source;  // if empty, the library's source at `path`
  std::vector<std::pair<std::string, std::string>> defines;
  // Deduced from the path's extension (.vert .frag .comp) when not given.
  std::optional<ShaderStage> stage;
};

struct ShaderDiagnostic {
  std::string file;
  int line = 0;
  std::string message;
};

// A shader that failed to compile: file and line of the first error, and all
// of glslang's messages. A value the caller handles, never an abort.
class ShaderCompileError : public std::runtime_error {
 public:
  ShaderCompileError(std::vector<ShaderDiagnostic> diagnostics, const std::string& log);
  const std::vector<ShaderDiagnostic>& diagnostics() const { return diagnostics_; }
  const std::string& file() const { return diagnostics_.front().file; }
  int line() const { return diagnostics_.front().line; }
  const std::string& log() const { return log_; }  // glslang's full output

 private:
  std::vector<ShaderDiagnostic> diagnostics_;
  std::string log_;
};

struct ShaderCompilerStats {
  uint64_t compiled = 0;    // glslang ran to SPIR-V
  uint64_t diskHits = 0;    // served from the on-disk cache
  uint64_t memoryHits = 0;  // served from this process's cache
};

// Default cache directory: $SG_CACHE_DIR, else $XDG_CACHE_HOME/shadelgraph, else ~/.cache/shadelgraph.
std::filesystem::path defaultCacheDirectory();

class ShaderCompiler {
 public:
  // An empty cacheDirectory disables the disk cache.
  ShaderCompiler(const ShaderLibrary& library, std::filesystem::path cacheDirectory = defaultCacheDirectory());
  std::vector<uint32_t> compile(const ShaderRequest& request);
  ShaderCompilerStats stats() const;

 private:
  const ShaderLibrary& library_;
  std::filesystem::path cacheDirectory_;
  mutable std::mutex mutex_;
  std::map<uint64_t, std::vector<uint32_t>> memory_;
  ShaderCompilerStats stats_;
};

}  // namespace sg::gpu
