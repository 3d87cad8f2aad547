#pragma once
// Shared helpers for the scene tests: where the test models are, and a
// temporary directory to write synthesized glTF files into.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace sg::scene::test {

// The Khronos sample models (see shared/assets/README.md).
// Sample models, assimp-testmodels and temporary directories: tests/support.
using sg::test::assetsDir;
using sg::test::assimpDir;
using sg::test::haveAssets;
using sg::test::haveAssimpModels;
using sg::test::samplePath;
using sg::test::TempDir;

// Little-endian bytes of floats / 16-bit / 32-bit values, to build .bin files.
std::vector<uint8_t> bytesOf(const std::vector<float>& values);
std::vector<uint8_t> bytesOf(const std::vector<uint16_t>& values);
std::vector<uint8_t> bytesOf(const std::vector<uint32_t>& values);
std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts);

// A glTF with one triangle mesh (36 bytes of POSITION in "triangle.bin") and
// whatever `nodes` / `extra` JSON the test adds: `nodes` is the nodes array's
// content, `extra` more top-level members (with a leading comma).
std::filesystem::path writeTriangleGltf(const TempDir& dir, const std::string& name, const std::string& nodes,
                                        const std::string& sceneNodes, const std::string& extra = "");

}  // namespace sg::scene::test

#define SG_REQUIRE_ASSIMP_MODELS()                                                                              \
  do {                                                                                                          \
    if (!::sg::scene::test::haveAssimpModels())                                                                 \
      GTEST_SKIP() << "assimp test models not found at " << ::sg::scene::test::assimpDir()                      \
                   << " (apt-get install assimp-testmodels)";                                                   \
  } while (0)
