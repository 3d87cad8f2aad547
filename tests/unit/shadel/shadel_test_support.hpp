#pragma once
// Shared helpers for the shadel tests: the sample models, small synthetic
// meshes, a temporary directory.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <shadelgraph/scene/mesh.hpp>

namespace sg::shadel::test {

// Sample models and temporary directories: tests/support.
using sg::test::allSamples;
using sg::test::assetsDir;
using sg::test::haveAssets;
using sg::test::samplePath;
using sg::test::TempDir;

// One primitive with TEXCOORD_0 = uvs and positions (u, v, 0).
scene::Mesh meshWithUvs(std::vector<glm::vec2> uvs, std::vector<uint32_t> indices);



}  // namespace sg::shadel::test
