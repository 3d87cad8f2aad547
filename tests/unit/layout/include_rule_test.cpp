// The layer rule on the real source tree (DESIGN.md, "Layout"):
//   framework  <-  materials, passes  <-  plugins  <-  apps
// each folder includes only itself and floors strictly below it, in C++ and
// GLSL alike. materials and passes share a floor as siblings and include
// neither each other: a pass must serve any material and a material any
// frame; what both need (Surface, lights, debug colours) belongs to the
// framework's material SDK.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <utility>

#include "include_scan.hpp"

namespace sg::test::layout {
namespace {

struct KnownViolation {
  const char* file;
  const char* include;  // as written, <x> or "x"
};

// Today's violations, every one. This list must only shrink, to empty: the
// frame/plugin redesign (issue 12) moves these files where they belong. The
// test fails on any violation missing here AND on any entry that no longer
// occurs, so fixing one means deleting its line.
const KnownViolation kKnownViolations[] = {
    // A debug material borrows a debug view's colours.
    {"materials/debug/detail_level.glsl", "<passes/debug-views/debug_color.glsl>"},
    // Passes include the glTF-PBR material's Surface.
    {"passes/forward/forward_surface.glsl", "<materials/gltf-pbr/material.glsl>"},
    {"passes/layer-shade/shadel_context.glsl", "<materials/gltf-pbr/material.glsl>"},
};

TEST(IncludeRule, EveryIncludeKeepsToTheFloors) {
  const std::filesystem::path root = SG_SOURCE_DIR;
  const LayoutReport report = checkLayout(root);
  // The scan read the tree (a wrong root would pass vacuously).
  ASSERT_GT(report.files, 100u) << "sources under " << root;
  ASSERT_GT(report.projectIncludes, 300u) << "project includes resolved under " << root;

  std::set<std::pair<std::string, std::string>> known, seen;
  for (const KnownViolation& k : kKnownViolations) known.insert({k.file, k.include});
  std::ostringstream fresh;
  for (const Violation& v : report.violations) {
    seen.insert({v.include.file, v.include.written()});
    if (!known.count({v.include.file, v.include.written()})) fresh << "  " << v.message() << "\n";
  }
  std::ostringstream stale;
  for (const auto& [file, include] : known)
    if (!seen.count({file, include}))
      stale << "  " << file << " includes " << include << " no longer: delete its line from kKnownViolations\n";
  std::ostringstream unresolved;
  for (const Include& i : report.unresolved)
    unresolved << "  " << i.file << ":" << i.line << " includes " << i.written()
               << ", which resolves to no file (a new include root? add it to kIncludeRoots in include_scan.cpp)\n";

  EXPECT_TRUE(fresh.str().empty()) << "layer rule violations (framework <- materials, passes <- plugins <- apps):\n"
                                   << fresh.str();
  EXPECT_TRUE(stale.str().empty()) << "stale known violations:\n" << stale.str();
  EXPECT_TRUE(unresolved.str().empty()) << unresolved.str();
  std::printf("%zu files, %zu project includes, %zu violations (%zu known)\n", report.files, report.projectIncludes,
              report.violations.size(), known.size());
}

}  // namespace
}  // namespace sg::test::layout
