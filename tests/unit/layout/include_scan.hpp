#pragma once
// The layer rule of DESIGN.md as code: every #include of the project's C++ and
// GLSL sources, resolved to the file it names, checked against the floors
//   framework  <-  materials, passes  <-  plugins  <-  apps
// (a folder may include itself and floors strictly below it).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace sg::test::layout {

// One top-level folder and its floor; higher floors may include lower ones.
struct Floor {
  std::string folder;
  int level;
};
// framework 0; materials and passes 1 (siblings: neither includes the other);
// plugins 2 (benchmarks too, a tool on the framework that only apps use); apps 3.
const std::vector<Floor>& floors();
const Floor* floorOf(const std::string& folder);

// An include as written: `<x>` or `"x"`, in a #include directive or, in C++,
// in a string literal (generated GLSL text, e.g. "#include <passes/...>\n").
struct Include {
  std::string file;  // including file, relative to the scanned root
  int line = 0;
  std::string path;  // between the brackets or quotes
  bool quoted = false;
  bool inStringLiteral = false;
  std::string written() const { return quoted ? "\"" + path + "\"" : "<" + path + ">"; }
};

// Every include of every .hpp/.cpp/.h/.glsl/.comp/.frag/.vert under the
// floors' folders of `root`, in path order; `fileCount`: how many files were read.
std::vector<Include> scanIncludes(const std::filesystem::path& root, size_t* fileCount = nullptr);

// The project file `include` names, relative to `root`: a quoted path against
// the including file's folder first (C++ and glslang's GL_GOOGLE_include_directive
// both do), then the include roots the build sets (see kIncludeRoots in
// include_scan.cpp). nullopt: a file outside the project (std, glm, Vulkan...).
std::optional<std::filesystem::path> resolveInclude(const std::filesystem::path& root, const Include& include);

// An include that names a project folder (<passes/...>, <shadelgraph/...>,
// "x.glsl" beside the file...) but no file: the include roots here are stale.
bool looksLikeProjectInclude(const std::filesystem::path& root, const Include& include);

struct Violation {
  Include include;
  std::string from;  // floor folder of the including file
  std::string to;    // floor folder of the included file
  std::string message() const;  // file:line includes <x> (floor A may not include floor B)
};

struct LayoutReport {
  std::vector<Violation> violations;
  std::vector<Include> unresolved;  // see looksLikeProjectInclude
  size_t files = 0;  // source files read
  size_t projectIncludes = 0;  // includes that resolved to a project file
};
LayoutReport checkLayout(const std::filesystem::path& root);

// The material SDK (issue 12): the umbrella a layer author includes, and the
// example plugins (plugins/example-*/), which include only it.
inline constexpr const char* kSdkUmbrella = "framework/plugin/shaders/material.glsl";
inline constexpr const char* kExamplePluginPrefix = "plugins/example-";

// The umbrella and every project file it includes, transitively (relative to `root`).
std::set<std::string> sdkFiles(const std::filesystem::path& root);

struct SdkReport {
  std::set<std::string> sdk;             // sdkFiles(root)
  std::vector<std::string> outside;      // "file:line includes <x> (resolves to y, not the SDK)"
  size_t exampleGlslFiles = 0;           // GLSL files read in the example plugins
  size_t checked = 0;                    // their includes
};
// Every include in the example plugins' GLSL (.glsl/.comp/.frag/.vert) must
// resolve to a file of the SDK or of the same plugin's folder; `outside` lists
// the rest (an include that resolves to no file is listed too).
SdkReport checkExampleSdkIncludes(const std::filesystem::path& root);

}  // namespace sg::test::layout
