#include "include_scan.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <regex>
#include <set>

namespace sg::test::layout {
namespace fs = std::filesystem;

const std::vector<Floor>& floors() {
  static const std::vector<Floor> kFloors = {{"framework", 0}, {"materials", 1}, {"passes", 1},
                                             {"plugins", 2},   {"benchmarks", 2}, {"apps", 3}};
  return kFloors;
}

const Floor* floorOf(const std::string& folder) {
  for (const Floor& f : floors())
    if (f.folder == folder) return &f;
  return nullptr;
}

namespace {

// Where the build looks for an include, relative to the project root: an
// include `prefix/rest` is tried as `dir/rest`. Keep in step with the build.
struct IncludeRoot {
  std::string prefix;
  std::string dir;
};
const IncludeRoot kIncludeRoots[] = {
    {"shadelgraph/", "framework/"},  // CMakeLists.txt: build/include/shadelgraph -> framework
    {"", ""},                        // GLSL virtual paths (cmake/ShaderEmbedding.cmake ROOT = the project)
    {"", "passes/"},                 // passes/CMakeLists.txt: target_include_directories(sg_passes ...)
    {"", "materials/"},              // materials/CMakeLists.txt
    {"", "plugins/"},                // plugins/CMakeLists.txt (forward recipe, decoupled)
    {"", "benchmarks/graph/"},       // benchmarks/graph/CMakeLists.txt (synthetic graphs for bench)
};

bool isSource(const fs::path& p) {
  static const std::set<std::string> kExtensions = {".hpp", ".cpp", ".h", ".glsl", ".comp", ".frag", ".vert"};
  return kExtensions.count(p.extension().string()) > 0;
}

bool isCpp(const fs::path& p) {
  const auto ext = p.extension().string();
  return ext == ".hpp" || ext == ".cpp" || ext == ".h";
}

std::string firstComponent(const fs::path& relative) {
  return relative.empty() ? std::string() : relative.begin()->string();
}

// `candidate` (absolute, lexically normal) as a regular file inside `root`.
std::optional<fs::path> inside(const fs::path& root, const fs::path& candidate) {
  const fs::path relative = candidate.lexically_normal().lexically_relative(root);
  if (relative.empty() || firstComponent(relative) == "..") return std::nullopt;
  std::error_code ec;
  if (!fs::is_regular_file(root / relative, ec)) return std::nullopt;
  return relative;
}

void scanFile(const fs::path& root, const fs::path& relative, std::vector<Include>& out) {
  // A directive: `#include <x>` / `#include "x"` at the start of a line.
  static const std::regex kDirective(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  // GLSL text a C++ string literal generates: "#include <x>\n" or "...\n#include \"x\"".
  static const std::regex kInLiteral(R"re((?:"|\\n)\s*#\s*include\s*(?:<([A-Za-z0-9_./+-]+)>|\\"([A-Za-z0-9_./+-]+)\\"))re");
  std::ifstream in(root / relative);
  std::string text;
  const bool cpp = isCpp(relative);
  for (int line = 1; std::getline(in, text); ++line) {
    std::smatch m;
    if (std::regex_search(text, m, kDirective)) {
      out.push_back({.file = relative.generic_string(), .line = line, .path = m[2].str(), .quoted = m[1] == "\""});
      continue;
    }
    if (!cpp) continue;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), kInLiteral); it != std::sregex_iterator(); ++it) {
      const bool quoted = (*it)[2].matched;
      out.push_back({.file = relative.generic_string(), .line = line, .path = (*it)[quoted ? 2 : 1].str(),
                     .quoted = quoted, .inStringLiteral = true});
    }
  }
}

}  // namespace

std::vector<Include> scanIncludes(const fs::path& root, size_t* fileCount) {
  std::vector<fs::path> files;
  for (const Floor& floor : floors()) {
    if (!fs::is_directory(root / floor.folder)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / floor.folder))
      if (entry.is_regular_file() && isSource(entry.path())) files.push_back(entry.path().lexically_relative(root));
  }
  std::sort(files.begin(), files.end());
  if (fileCount) *fileCount = files.size();
  std::vector<Include> out;
  for (const fs::path& f : files) scanFile(root, f, out);
  return out;
}

std::optional<fs::path> resolveInclude(const fs::path& root, const Include& include) {
  // Quoted: beside the including file first. Generated GLSL (a string literal)
  // has no folder of its own, only the roots.
  if (include.quoted && !include.inStringLiteral)
    if (auto found = inside(root, root / fs::path(include.file).parent_path() / include.path)) return found;
  for (const IncludeRoot& r : kIncludeRoots) {
    if (include.path.rfind(r.prefix, 0) != 0) continue;
    if (auto found = inside(root, root / r.dir / include.path.substr(r.prefix.size()))) return found;
  }
  return std::nullopt;
}

bool looksLikeProjectInclude(const fs::path& root, const Include& include) {
  if (include.quoted) return true;  // the project's quoted includes are all its own files
  const std::string first = firstComponent(fs::path(include.path));
  if (first == "shadelgraph" || floorOf(first)) return true;
  // <forward/...>, <decoupled/...>: a folder under one of the include roots.
  std::error_code ec;
  for (const IncludeRoot& r : kIncludeRoots)
    if (!r.dir.empty() && fs::is_directory(root / r.dir / first, ec)) return true;
  return false;
}

std::string Violation::message() const {
  return include.file + ":" + std::to_string(include.line) + " includes " + include.written() + " (floor " + from +
         " may not include floor " + to + ")";
}

LayoutReport checkLayout(const fs::path& root) {
  LayoutReport report;
  for (const Include& include : scanIncludes(root, &report.files)) {
    const auto target = resolveInclude(root, include);
    if (!target) {
      if (looksLikeProjectInclude(root, include)) report.unresolved.push_back(include);
      continue;
    }
    ++report.projectIncludes;
    const std::string from = firstComponent(fs::path(include.file)), to = firstComponent(*target);
    const Floor* a = floorOf(from);
    const Floor* b = floorOf(to);
    // Its own folder, or a floor strictly below; files outside every floor
    // (tests/, tools/) are never the framework's business to include.
    const bool allowed = from == to || (a && b && b->level < a->level);
    if (!allowed) report.violations.push_back({include, from, to});
  }
  return report;
}

namespace {

bool isGlsl(const fs::path& p) {
  const auto ext = p.extension().string();
  return ext == ".glsl" || ext == ".comp" || ext == ".frag" || ext == ".vert";
}

// "plugins/example-x/" for a file under plugins/example-x/, else "".
std::string examplePluginFolder(const std::string& file) {
  if (file.rfind(kExamplePluginPrefix, 0) != 0) return {};
  const auto slash = file.find('/', std::string(kExamplePluginPrefix).size());
  return slash == std::string::npos ? std::string() : file.substr(0, slash + 1);
}

}  // namespace

std::set<std::string> sdkFiles(const fs::path& root) {
  std::set<std::string> sdk;
  std::vector<std::string> pending = {kSdkUmbrella};
  std::error_code ec;
  if (!fs::is_regular_file(root / kSdkUmbrella, ec)) return sdk;
  // Includes per file, read once (the SDK is under framework/, a floor scanIncludes reads).
  std::map<std::string, std::vector<Include>> byFile;
  for (Include& i : scanIncludes(root)) byFile[i.file].push_back(std::move(i));
  while (!pending.empty()) {
    const std::string file = pending.back();
    pending.pop_back();
    if (!sdk.insert(file).second) continue;
    for (const Include& i : byFile[file])
      if (auto target = resolveInclude(root, i)) pending.push_back(target->generic_string());
  }
  return sdk;
}

SdkReport checkExampleSdkIncludes(const fs::path& root) {
  SdkReport report;
  report.sdk = sdkFiles(root);
  std::set<std::string> glslFiles;
  for (const Include& i : scanIncludes(root)) {
    const std::string own = examplePluginFolder(i.file);
    if (own.empty() || !isGlsl(i.file)) continue;
    glslFiles.insert(i.file);
    ++report.checked;
    const auto target = resolveInclude(root, i);
    const std::string where = i.file + ":" + std::to_string(i.line) + " includes " + i.written();
    if (!target) {
      report.outside.push_back(where + " (resolves to no file; the SDK is <" + kSdkUmbrella + ">)");
      continue;
    }
    const std::string t = target->generic_string();
    if (report.sdk.count(t) || t.rfind(own, 0) == 0) continue;
    report.outside.push_back(where + " (" + t + " is not in the material SDK: include <" + kSdkUmbrella +
                             "> only)");
  }
  // Example GLSL files without any include count too (they were read).
  std::error_code ec;
  if (fs::is_directory(root / "plugins", ec))
    for (const auto& entry : fs::recursive_directory_iterator(root / "plugins")) {
      const std::string rel = entry.path().lexically_relative(root).generic_string();
      if (entry.is_regular_file() && isGlsl(entry.path()) && !examplePluginFolder(rel).empty()) glslFiles.insert(rel);
    }
  report.exampleGlslFiles = glslFiles.size();
  return report;
}

}  // namespace sg::test::layout
