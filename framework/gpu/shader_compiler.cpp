#include <shadelgraph/gpu/shader_compiler.hpp>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace sg::gpu {
namespace {

// glslang's process-wide state; initialized once, finalized at exit.
struct GlslangProcess {
  GlslangProcess() { glslang::InitializeProcess(); }
  ~GlslangProcess() { glslang::FinalizeProcess(); }
};
void ensureGlslang() { static GlslangProcess process; }

EShLanguage toGlslang(ShaderStage s) {
  switch (s) {
    case ShaderStage::Vertex: return EShLangVertex;
    case ShaderStage::Fragment: return EShLangFragment;
    case ShaderStage::Compute: return EShLangCompute;
  }
  return EShLangCompute;
}

ShaderStage stageFromPath(const std::string& path) {
  const auto ext = std::filesystem::path(path).extension();
  if (ext == ".vert") return ShaderStage::Vertex;
  if (ext == ".frag") return ShaderStage::Fragment;
  if (ext == ".comp") return ShaderStage::Compute;
  throw ShaderCompileError({{path, 0, "cannot tell the shader stage from the extension (use .vert, .frag, .comp)"}}, "");
}

// Resolves #include "x" relative to the including file, then from the library root.
class LibraryIncluder : public glslang::TShader::Includer {
 public:
  explicit LibraryIncluder(const ShaderLibrary& library) : library_(library) {}
  IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
    auto dir = std::filesystem::path(includer).parent_path();
    return load((dir / header).lexically_normal().generic_string());
  }
  IncludeResult* includeSystem(const char* header, const char*, size_t) override { return load(header); }
  void releaseInclude(IncludeResult* result) override {
    if (result) delete static_cast<std::string*>(result->userData);
    delete result;
  }

 private:
  IncludeResult* load(const std::string& path) {
    auto source = library_.find(path);
    if (!source) return nullptr;
    auto* text = new std::string(std::move(*source));
    return new IncludeResult(path, text->data(), text->size(), text);
  }
  const ShaderLibrary& library_;
};

// "ERROR: file:line: message" -> diagnostics.
std::vector<ShaderDiagnostic> parseLog(const std::string& log, const std::string& fallbackFile) {
  std::vector<ShaderDiagnostic> out;
  static const std::regex re(R"(ERROR: ([^:\n]+):(\d+): ([^\n]*))");
  for (std::sregex_iterator it(log.begin(), log.end(), re), end; it != end; ++it)
    out.push_back({(*it)[1].str(), std::stoi((*it)[2].str()), (*it)[3].str()});
  if (out.empty()) out.push_back({fallbackFile, 0, log.empty() ? "unknown glslang error" : log});
  return out;
}

uint64_t fnv1a(const std::string& text, uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

}  // namespace

ShaderCompileError::ShaderCompileError(std::vector<ShaderDiagnostic> diagnostics, const std::string& log)
    : std::runtime_error([&] {
        const auto& d = diagnostics.front();
        std::string what = d.file + ":" + std::to_string(d.line) + ": " + d.message;
        if (diagnostics.size() > 1) what += " (and " + std::to_string(diagnostics.size() - 1) + " more)";
        return what;
      }()),
      diagnostics_(std::move(diagnostics)),
      log_(log) {}

std::filesystem::path defaultCacheDirectory() {
  if (const char* d = std::getenv("SG_CACHE_DIR")) return d;
  if (const char* x = std::getenv("XDG_CACHE_HOME")) return std::filesystem::path(x) / "shadelgraph";
  if (const char* h = std::getenv("HOME")) return std::filesystem::path(h) / ".cache" / "shadelgraph";
  return std::filesystem::temp_directory_path() / "shadelgraph-cache";
}

ShaderCompiler::ShaderCompiler(const ShaderLibrary& library, std::filesystem::path cacheDirectory)
    : library_(library), cacheDirectory_(std::move(cacheDirectory)) {
  ensureGlslang();
}

ShaderCompilerStats ShaderCompiler::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

std::vector<uint32_t> ShaderCompiler::compile(const ShaderRequest& request) {
  std::string source = request.source;
  if (source.empty()) {
    auto found = library_.find(request.path);
    if (!found) throw ShaderCompileError({{request.path, 0, "shader source not found"}}, "");
    source = std::move(*found);
  }
  const ShaderStage stage = request.stage ? *request.stage : stageFromPath(request.path);
  const EShLanguage lang = toGlslang(stage);

  std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
  for (const auto& [name, value] : request.defines) preamble += "#define " + name + " " + value + "\n";

  const char* text = source.c_str();
  const int length = static_cast<int>(source.size());
  const char* name = request.path.c_str();
  auto makeShader = [&] {
    auto shader = std::make_unique<glslang::TShader>(lang);
    shader->setStringsWithLengthsAndNames(&text, &length, &name, 1);
    shader->setPreamble(preamble.c_str());
    shader->setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
    shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
    shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
    return shader;
  };
  const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  LibraryIncluder includer(library_);

  // The cache key covers everything that changes the output: the fully
  // preprocessed text (includes expanded, defines applied), stage and glslang.
  std::string preprocessed;
  {
    auto shader = makeShader();
    if (!shader->preprocess(GetDefaultResources(), 460, ENoProfile, false, false, messages, &preprocessed, includer))
      throw ShaderCompileError(parseLog(shader->getInfoLog(), request.path), shader->getInfoLog());
  }
  const uint64_t key = fnv1a(std::to_string(static_cast<int>(stage)) + glslang::GetGlslVersionString() +
                             "spv1.6/vk1.3\n" + preprocessed);
  const auto cacheFile = cacheDirectory_.empty() ? std::filesystem::path() : cacheDirectory_ / "shaders" / (hex(key) + ".spv");
  {
    std::lock_guard lock(mutex_);
    if (auto it = memory_.find(key); it != memory_.end()) {
      ++stats_.memoryHits;
      return it->second;
    }
  }
  if (!cacheFile.empty()) {
    std::ifstream in(cacheFile, std::ios::binary | std::ios::ate);
    if (in && in.tellg() > 0 && in.tellg() % 4 == 0) {
      std::vector<uint32_t> spirv(static_cast<size_t>(in.tellg()) / 4);
      in.seekg(0);
      in.read(reinterpret_cast<char*>(spirv.data()), static_cast<std::streamsize>(spirv.size() * 4));
      if (in && spirv[0] == 0x07230203u) {
        std::lock_guard lock(mutex_);
        ++stats_.diskHits;
        memory_[key] = spirv;
        return spirv;
      }
    }
  }

  auto shader = makeShader();
  if (!shader->parse(GetDefaultResources(), 460, false, messages, includer))
    throw ShaderCompileError(parseLog(shader->getInfoLog(), request.path), shader->getInfoLog());
  glslang::TProgram program;
  program.addShader(shader.get());
  if (!program.link(messages))
    throw ShaderCompileError(parseLog(program.getInfoLog(), request.path), program.getInfoLog());
  std::vector<uint32_t> spirv;
  glslang::SpvOptions options;
  options.generateDebugInfo = false;
  options.validate = false;
  glslang::GlslangToSpv(*program.getIntermediate(lang), spirv, &options);

  if (!cacheFile.empty()) {
    // Write to a temporary name and rename, so a concurrent reader never sees half a file.
    std::error_code ec;
    std::filesystem::create_directories(cacheFile.parent_path(), ec);
    auto tmp = cacheFile;
    tmp += ".tmp" + std::to_string(reinterpret_cast<uintptr_t>(&spirv));
    {
      std::ofstream out(tmp, std::ios::binary);
      out.write(reinterpret_cast<const char*>(spirv.data()), static_cast<std::streamsize>(spirv.size() * 4));
    }
    std::filesystem::rename(tmp, cacheFile, ec);
  }
  std::lock_guard lock(mutex_);
  ++stats_.compiled;
  memory_[key] = spirv;
  return spirv;
}

}  // namespace sg::gpu
