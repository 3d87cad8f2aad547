// Bad input: every malformed file fails with a one-line SceneError naming
// what is wrong, and nothing crashes.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <random>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <shadelgraph/scene/gltf_loader.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using test::TempDir;
using ::testing::HasSubstr;

// The message of the SceneError that loading `file` throws; fails the test
// if loading succeeds or throws anything else.
std::string loadError(const std::filesystem::path& file) {
  try {
    loadGltf(file);
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << "starts with the file: " << message;
    return message;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw something other than SceneError: " << error.what();
    return {};
  }
  ADD_FAILURE() << file << " loaded, but it is malformed";
  return {};
}

struct MalformedCase {
  const char* file;      // relative to the assimp models' glTF2 folder
  const char* expected;  // substring of the message

  friend void PrintTo(const MalformedCase& c, std::ostream* out) { *out << c.file; }
};

// Each was read by hand: what the file gets wrong, and the message naming it.
const MalformedCase kAssimpCases[] = {
    {"IndexOutOfRange/IndexOutOfRange.gltf", "mesh 0 'Mesh' primitive 0: index 255 (indices[0]) is out of range: the primitive has 24 vertices"},
    {"IndexOutOfRange/AllIndicesOutOfRange.gltf", "index 65535 (indices[0]) is out of range"},
    {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "POSITION 0 is not finite: (-inf, -0.5, 0.5)"},
    // Four zero normals (one face) and four of length 0.1: glTF requires unit normals.
    {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", "NORMAL 0 has zero length"},
    {"MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
    {"RecursiveNodes/RecursiveNodes.gltf", "node hierarchy has a cycle: node 0 -> node 1 -> node 0"},
    // Also lacks its .bin; the type error is reported first.
    {"SchemaFailures/sceneWrongType.gltf", "scene: expected an integer >= 0, got the string \"hello\""},
    {"wrongTypes/badArray.gltf", "/meshes/0/primitives: expected an array, got an object"},
    {"wrongTypes/badExtension.gltf", "baseColorTexture/extensions/KHR_texture_transform: expected an object"},
    // "scale": "not a number" in a normalTexture that also lacks its index.
    {"wrongTypes/badNumber.gltf", "/materials/0/normalTexture"},
    {"wrongTypes/badObject.gltf", "/materials/0/pbrMetallicRoughness: expected an object, got an array"},
    {"wrongTypes/badString.gltf", "/scenes/0/name: expected a string, got the number 42"},
    {"wrongTypes/badUint.gltf", "baseColorTexture/index: expected an integer >= 0, got the number -1"},
    // Not in the brief's list, also malformed:
    {"IncorrectVertexArrays/Cube.gltf", "/bufferViews/2: bytes at offset 504, length 432 do not fit buffer 0's byteLength 514 (BUFFER_VIEW_TOO_LONG)"},
    {"TestNoRootNode/NoScene.gltf", "scene 0 does not exist"},
    {"draco/2CylinderEngine.gltf", "requires the unsupported extension KHR_draco_mesh_compression"},
    {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "requires the unsupported extension KHR_technique_webgl"},
};

class AssimpMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(AssimpMalformed, FailsWithClearMessage) {
  SG_REQUIRE_ASSIMP_MODELS();
  const std::filesystem::path file = test::assimpDir() / GetParam().file;
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  EXPECT_THAT(loadError(file), HasSubstr(GetParam().expected));
}

INSTANTIATE_TEST_SUITE_P(Files, AssimpMalformed, ::testing::ValuesIn(kAssimpCases),
                         [](const ::testing::TestParamInfo<MalformedCase>& param) {
                           std::string name = std::filesystem::path(param.param.file).parent_path().string() + "_" +
                                              std::filesystem::path(param.param.file).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// The rest of the assimp set is valid (or valid enough) and loads.
TEST(AssimpWellFormed, Load) {
  SG_REQUIRE_ASSIMP_MODELS();
  for (const char* file : {"TestNoRootNode/SceneWithoutNodes.gltf", "issue_3269/texcoord_crash.gltf",
                           "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", "BoxTexcoords-glTF/boxTexcoords.gltf",
                           "2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "ClearCoat-glTF/ClearCoatTest.gltf",
                           "cameras/Cameras.gltf", "simple_skin/simple_skin.gltf", "textureTransform/TextureTransformTest.gltf",
                           "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"}) {
    SCOPED_TRACE(file);
    EXPECT_NO_THROW(loadGltf(test::assimpDir() / file, LoadOptions{.decodeImages = false}));
  }
}

TEST(MalformedGltf, MissingTextureIsAnError) {
  SG_REQUIRE_ASSETS();
  TempDir dir;
  const std::filesystem::path source = test::assetsDir() / "BoxTextured/glTF";
  std::filesystem::copy_file(source / "BoxTextured.gltf", dir.path() / "BoxTextured.gltf");
  std::filesystem::copy_file(source / "BoxTextured0.bin", dir.path() / "BoxTextured0.bin");
  const std::string message = loadError(dir.path() / "BoxTextured.gltf");
  EXPECT_THAT(message, HasSubstr("image 'CesiumLogoFlat.png'"));
  EXPECT_THAT(message, HasSubstr("baseColorTexture"));
  EXPECT_THAT(message, HasSubstr("missing"));
  // Even when only the header would be read.
  EXPECT_THROW(loadGltf(dir.path() / "BoxTextured.gltf", LoadOptions{.decodeImages = false}), SceneError);
}

TEST(MalformedGltf, UndecodableTextureIsAnError) {
  SG_REQUIRE_ASSETS();
  TempDir dir;
  const std::filesystem::path source = test::assetsDir() / "BoxTextured/glTF";
  std::filesystem::copy_file(source / "BoxTextured.gltf", dir.path() / "BoxTextured.gltf");
  std::filesystem::copy_file(source / "BoxTextured0.bin", dir.path() / "BoxTextured0.bin");
  dir.write("CesiumLogoFlat.png", "this is not a PNG");
  const std::string message = loadError(dir.path() / "BoxTextured.gltf");
  EXPECT_THAT(message, HasSubstr("image 'CesiumLogoFlat.png'"));
  EXPECT_THAT(message, HasSubstr("cannot be decoded"));
}

TEST(MalformedGltf, FileProblems) {
  TempDir dir;
  EXPECT_THAT(loadError(dir.path() / "absent.gltf"), HasSubstr("no such file"));
  EXPECT_THAT(loadError(dir.write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"")), HasSubstr("invalid JSON"));
  EXPECT_THAT(loadError(dir.write("array.gltf", "[1, 2]")), HasSubstr("the document: expected an object"));
  EXPECT_THAT(loadError(dir.write("noasset.gltf", "{}")), HasSubstr("asset: required property is missing"));
  // A .glb header promising more than the file holds: tinygltf's error.
  std::vector<uint8_t> glb = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 200, 0, 0, 0, 100, 0, 0, 0, 'J', 'S', 'O', 'N'};
  EXPECT_FALSE(loadError(dir.write("short.glb", glb)).empty());
}

// One-triangle files with one thing wrong each.
struct SynthesizedCase {
  const char* name;
  const char* nodes;
  const char* sceneNodes;
  const char* extra;
  const char* expected;

  friend void PrintTo(const SynthesizedCase& c, std::ostream* out) { *out << c.name; }
};

const SynthesizedCase kSynthesizedCases[] = {
    {"TwoParents", R"({"children": [2]}, {"children": [2]}, {"mesh": 0})", "0, 1", "",
     "node 2 has two parents, node 0 and node 1"},
    {"OwnChild", R"({"children": [0]})", "0", "", "node 0 is its own child"},
    {"LongCycle", R"({"mesh": 0}, {"children": [2]}, {"children": [3]}, {"children": [1]})", "0", "",
     "cycle: node 1 -> node 2 -> node 3 -> node 1"},
    {"RootIsChild", R"({"children": [1]}, {"mesh": 0})", "0, 1", "", "lists node 1 as a root, but it is a child of node 0"},
    {"MissingChild", R"({"children": [7]})", "0", "", "/nodes/0/children/0: node 7 does not exist (the file has 1)"},
    {"MissingMesh", R"({"mesh": 3})", "0", "", "/nodes/0/mesh: mesh 3 does not exist (the file has 1)"},
    {"MissingSceneNode", R"({"mesh": 0})", "4", "", "/scenes/0/nodes/0: node 4 does not exist"},
    {"MissingCamera", R"({"camera": 0})", "0", "", "/nodes/0/camera: camera 0 does not exist"},
    {"MissingLight", R"({"extensions": {"KHR_lights_punctual": {"light": 2}}})", "0", "", "/nodes/0/extensions/KHR_lights_punctual/light: light 2 does not exist"},
    {"BadCamera", R"({"camera": 0})", "0", R"(, "cameras": [{"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}}])",
     "camera 0: perspective camera needs yfov > 0"},
    {"UnsupportedRequiredExtension", R"({"mesh": 0})", "0", R"(, "extensionsRequired": ["KHR_mesh_quantization"])",
     "requires the unsupported extension KHR_mesh_quantization"},
    {"NonFiniteMatrix", R"({"mesh": 0, "scale": [1, 1e39, 1]})", "0", "", "/nodes/0/scale/1: expected a number within the range of a 32-bit float, got the number 1e+39"},
};

class SynthesizedMalformed : public ::testing::TestWithParam<SynthesizedCase> {};

TEST_P(SynthesizedMalformed, FailsWithClearMessage) {
  TempDir dir;
  const SynthesizedCase& c = GetParam();
  EXPECT_THAT(loadError(test::writeTriangleGltf(dir, "bad.gltf", c.nodes, c.sceneNodes, c.extra)), HasSubstr(c.expected));
}

INSTANTIATE_TEST_SUITE_P(Files, SynthesizedMalformed, ::testing::ValuesIn(kSynthesizedCases),
                         [](const ::testing::TestParamInfo<SynthesizedCase>& param) { return std::string(param.param.name); });

// Accessor-level problems, in a file whose accessors the test writes.
std::filesystem::path writeAccessorGltf(const TempDir& dir, const std::string& primitive, const std::string& accessors,
                                        const std::string& bufferViews, size_t bufferBytes) {
  std::vector<uint8_t> bytes(bufferBytes, 0);
  const std::vector<uint8_t> triangle = test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  std::copy(triangle.begin(), triangle.begin() + static_cast<std::ptrdiff_t>(std::min(bufferBytes, triangle.size())),
            bytes.begin());
  dir.write("data.bin", bytes);
  return dir.write("accessors.gltf", R"({
  "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"name": "m", "primitives": [)" + primitive + R"(]}],
  "accessors": [)" + accessors + R"(],
  "bufferViews": [)" + bufferViews + R"(],
  "buffers": [{"uri": "data.bin", "byteLength": )" + std::to_string(bufferBytes) + "}]}");
}

TEST(MalformedGltf, AccessorOutsideItsBufferView) {
  TempDir dir;
  const auto file = writeAccessorGltf(dir, R"({"attributes": {"POSITION": 0}})",
                                      R"({"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"})",
                                      R"({"buffer": 0, "byteLength": 36})", 36);
  EXPECT_THAT(loadError(file), HasSubstr("/accessors/0: 4 elements of 12 bytes from offset 0 do not fit its bufferView's 36 bytes (ACCESSOR_TOO_LONG)"));
}

TEST(MalformedGltf, BufferViewOutsideItsBuffer) {
  TempDir dir;
  const auto file = writeAccessorGltf(dir, R"({"attributes": {"POSITION": 0}})",
                                      R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"})",
                                      R"({"buffer": 0, "byteOffset": 8, "byteLength": 36})", 36);
  EXPECT_THAT(loadError(file), HasSubstr("/bufferViews/0: bytes at offset 8, length 36 do not fit buffer 0's byteLength 36 (BUFFER_VIEW_TOO_LONG)"));
}

TEST(MalformedGltf, StrideSmallerThanElement) {
  TempDir dir;
  const auto file = writeAccessorGltf(dir, R"({"attributes": {"POSITION": 0}})",
                                      R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"})",
                                      R"({"buffer": 0, "byteLength": 36, "byteStride": 8})", 36);
  EXPECT_THAT(loadError(file), HasSubstr("byteStride 8 is smaller than its 12-byte elements"));
}

TEST(MalformedGltf, WrongComponentTypes) {
  {
    TempDir dir;
    const auto file = writeAccessorGltf(dir, R"({"attributes": {"POSITION": 0}})",
                                        R"({"bufferView": 0, "componentType": 5123, "count": 3, "type": "VEC3"})",
                                        R"({"buffer": 0, "byteLength": 36})", 36);
    EXPECT_THAT(loadError(file), HasSubstr("POSITION (accessor 0) is VEC3 of UNSIGNED_SHORT; expected VEC3 of FLOAT"));
  }
  {
    TempDir dir;
    const auto file = writeAccessorGltf(
        dir, R"({"attributes": {"POSITION": 0, "TEXCOORD_0": 1}})",
        R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
           {"bufferView": 0, "componentType": 5123, "count": 3, "type": "VEC2"})",
        R"({"buffer": 0, "byteLength": 36})", 36);
    EXPECT_THAT(loadError(file), HasSubstr("TEXCOORD_0 (accessor 1) is VEC2 of UNSIGNED_SHORT; expected VEC2 of FLOAT, "
                                           "or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT"));
  }
  {
    TempDir dir;
    const auto file = writeAccessorGltf(
        dir, R"({"attributes": {"POSITION": 0}, "indices": 1})",
        R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
           {"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR"})",
        R"({"buffer": 0, "byteLength": 36})", 36);
    EXPECT_THAT(loadError(file), HasSubstr("indices (accessor 1) are SCALAR of FLOAT; expected SCALAR of UNSIGNED_BYTE"));
  }
  {
    TempDir dir;
    const auto file = writeAccessorGltf(dir, R"({"attributes": {"POSITION": 0}})",
                                        R"({"bufferView": 0, "componentType": 5124, "count": 3, "type": "VEC3"})",
                                        R"({"buffer": 0, "byteLength": 36})", 36);
    EXPECT_THAT(loadError(file), HasSubstr("/accessors/0/componentType: expected one of"));
  }
}

TEST(MalformedGltf, AttributeCountMismatch) {
  TempDir dir;
  const auto file = writeAccessorGltf(
      dir, R"({"attributes": {"POSITION": 0, "NORMAL": 1}})",
      R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
         {"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3"})",
      R"({"buffer": 0, "byteLength": 36})", 36);
  EXPECT_THAT(loadError(file), HasSubstr("NORMAL has 2 elements, POSITION has 3"));
}

TEST(MalformedGltf, SparseIndexOutOfRange) {
  TempDir dir;
  // Sparse index 9 in a 3-element accessor: 36 bytes of positions, then the
  // index (uint16 9 padded to 4 bytes), then one 12-byte value.
  const auto file = writeAccessorGltf(
      dir, R"({"attributes": {"POSITION": 0}})",
      R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
          "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 2}}})",
      R"({"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 2},
         {"buffer": 0, "byteOffset": 40, "byteLength": 12})",
      52);
  // Patch the index to 9.
  std::vector<uint8_t> bytes(52, 0);
  const auto triangle = test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  std::copy(triangle.begin(), triangle.end(), bytes.begin());
  bytes[36] = 9;
  dir.write("data.bin", bytes);
  EXPECT_THAT(loadError(file), HasSubstr("sparse index 9 is out of range (count 3)"));
}

TEST(MalformedGltf, MissingMaterial) {
  TempDir dir;
  const auto file = writeAccessorGltf(dir, R"({"attributes": {"POSITION": 0}, "material": 2})",
                                      R"({"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"})",
                                      R"({"buffer": 0, "byteLength": 36})", 36);
  EXPECT_THAT(loadError(file), HasSubstr("/meshes/0/primitives/0/material: material 2 does not exist (the file has 0)"));
}

TEST(MalformedGltf, NanNormal) {
  TempDir dir;
  std::vector<float> values{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, std::nanf(""), 0, 1};
  dir.write("data.bin", test::bytesOf(values));
  const auto file = dir.write("nan.gltf", R"({
  "asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 72}],
  "buffers": [{"uri": "data.bin", "byteLength": 72}]})");
  EXPECT_THAT(loadError(file), HasSubstr("NORMAL 2 is not finite"));
}

// Deterministic corruption of valid files (bytes overwritten, files cut
// short): every load either works or throws SceneError, never anything else,
// and never crashes. A cheap stand-in for fuzzing, run on every test run.
TEST(MalformedGltf, CorruptedFilesNeverCrash) {
  SG_REQUIRE_ASSETS();
  TempDir dir;
  const std::filesystem::path source = test::assetsDir() / "BoxTextured/glTF";
  for (const char* name : {"BoxTextured.gltf", "BoxTextured0.bin", "CesiumLogoFlat.png"})
    std::filesystem::copy_file(source / name, dir.path() / name);
  std::mt19937 random(20240531);
  for (const char* victim : {"BoxTextured0.bin", "BoxTextured.gltf", "CesiumLogoFlat.png"}) {
    std::ifstream in(source / victim, std::ios::binary);
    const std::vector<uint8_t> original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t loaded = 0, rejected = 0;
    for (int round = 0; round < 150; ++round) {
      std::vector<uint8_t> bytes = original;
      if (round % 4 == 0) {
        bytes.resize(random() % bytes.size());
      } else {
        for (uint32_t n = 1 + random() % 6; n > 0; --n) bytes[random() % bytes.size()] = static_cast<uint8_t>(random());
      }
      dir.write(victim, bytes);
      try {
        loadGltf(dir.path() / "BoxTextured.gltf");
        ++loaded;
      } catch (const SceneError&) {
        ++rejected;
      } catch (const std::exception& error) {
        ADD_FAILURE() << victim << " round " << round << ": " << error.what();
      }
    }
    dir.write(victim, original);
    EXPECT_GT(rejected, 0u) << victim << ": " << loaded << " loaded";
  }
}

}  // namespace
}  // namespace sg::scene
