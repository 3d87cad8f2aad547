// Hostile files through the CLI (issue 13): `inspect` and `render` answer each
// with exactly one line `shadelgraph: error: <file>: ...` on stderr and exit
// code 1, never a crash, a flood of text or a silent success. The loader-level
// cases are in tests/unit/scene/hostile_input_test.cpp; docs/hostile-input.md
// has the decisions.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_run.hpp"
#include "test_support.hpp"

namespace {

using Json = nlohmann::json;
using sg::test::TempDir;

sg::test::CliOutputs run(const std::string& args, const std::filesystem::path& errFile) {
  return sg::test::runCliApart(args, errFile);
}

std::vector<uint8_t> triangleBin() {
  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const uint16_t indices[] = {0, 1, 2, 0};
  std::vector<uint8_t> bytes(44);
  std::memcpy(bytes.data(), positions, 36);
  std::memcpy(bytes.data() + 36, indices, 8);
  return bytes;
}

Json triangle() {
  return Json::parse(R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"uri": "triangle.bin", "byteLength": 44}]})");
}

// A .glb with only a JSON chunk.
std::vector<uint8_t> glbOf(std::string json, uint32_t version) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::vector<uint8_t> out{'g', 'l', 'T', 'F'};
  const auto u32 = [&](uint32_t v) {
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<uint8_t>(v >> shift));
  };
  u32(version);
  u32(static_cast<uint32_t>(20 + json.size()));
  u32(static_cast<uint32_t>(json.size()));
  u32(0x4E4F534Au);
  for (const char c : json) out.push_back(static_cast<uint8_t>(c));
  return out;
}

struct HostileFile {
  const char* name;      // file name; its extension picks the loader
  const char* expected;  // substring of the error line
};

// Each writes its file into `dir`.
std::filesystem::path writeHostile(const TempDir& dir, const std::string& name) {
  dir.write("triangle.bin", triangleBin());
  Json document = triangle();
  if (name == "deep-extras.gltf") {
    std::string text = document.dump();
    text.insert(text.find("\"mesh\":0"), "\"extras\":" + std::string(16000, '[') + std::string(16000, ']') + ",");
    return dir.write(name, text);
  }
  if (name == "offset-near-2-64.gltf") document["accessors"][0]["byteOffset"] = 18446744073709551600ull;
  if (name == "mesh-2-32.gltf") document["nodes"][0]["mesh"] = 4294967296ull;
  if (name == "index-count-2-32.gltf") document["accessors"][1]["count"] = 4294967295u;
  if (name == "sparse-2-62.gltf")
    document["accessors"][0] = Json::parse(R"({"componentType": 5126, "count": 4611686018427387904, "type": "VEC3",
        "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}}})");
  if (name == "cycle.gltf") {
    Json& nodes = document["nodes"] = Json::array();
    for (int i = 0; i < 50000; ++i) nodes.push_back({{"children", {(i + 1) % 50000}}});
  }
  if (name == "data-uri.gltf") document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + std::string(68000, '!');
  if (name == "version-1.glb") {
    document["buffers"][0]["byteLength"] = 1;
    document["buffers"][0]["uri"] = "triangle.bin";
    return dir.write(name, glbOf(document.dump(), 1));
  }
  if (name == "number-1e999.gltf") {
    std::string text = document.dump();
    text.replace(text.find("\"max\":[1,1,0]"), 13, "\"max\":[1,1e999,0]");
    return dir.write(name, text);
  }
  if (name == "translation-1e39.json") {
    dir.write("triangle.gltf", document.dump());
    return dir.write(name, R"({"objects": [{"gltf": "triangle.gltf", "translation": [0, 1e39, 0]}]})");
  }
  if (name == "orbit-1e39.json") {
    dir.write("triangle.gltf", document.dump());
    return dir.write(name, R"({"objects": [{"gltf": "triangle.gltf"}], "cameraPaths": [{"type": "orbit", "radius": 1e39}]})");
  }
  // Environment images (a scene file's "environment"): missing, not Radiance, a bad format line, a huge claimed size.
  if (name.rfind("hdr-", 0) == 0) {
    dir.write("triangle.gltf", document.dump());
    if (name == "hdr-not-radiance.json") dir.write("sky.hdr", std::string("P3\n1 1\n255\n0 0 0\n"));
    if (name == "hdr-bad-format.json") dir.write("sky.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 4\n"));
    if (name == "hdr-huge.json")
      dir.write("sky.hdr", std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 100000 +X 200000\n") + std::string(64, '\x01'));
    return dir.write(name, R"({"objects": [{"gltf": "triangle.gltf"}], "environment": {"image": "sky.hdr"}})");
  }
  // A material extension this renderer does not implement, required: refused by name, not rendered without it.
  if (name == "requires-transmission.gltf") {
    document["extensionsUsed"] = Json::array({"KHR_materials_transmission"});
    document["extensionsRequired"] = Json::array({"KHR_materials_transmission"});
  }
  if (name == "deep.json") return dir.write(name, "{\"objects\": " + std::string(16000, '[') + std::string(16000, ']') + "}");
  return dir.write(name, document.dump());
}

const HostileFile kFiles[] = {
    {"deep-extras.gltf", "JSON nested deeper than 256 levels"},
    {"offset-near-2-64.gltf", "/accessors/0/byteOffset: 18446744073709551600 is past the end of its bufferView"},
    {"mesh-2-32.gltf", "/nodes/0/mesh: mesh 4294967296 does not exist (the file has 1)"},
    {"index-count-2-32.gltf", "/accessors/1: 4294967295 elements of 2 bytes"},
    {"sparse-2-62.gltf", "/accessors/0/count: 4611686018427387904 elements without a bufferView"},
    {"cycle.gltf", "node hierarchy has a cycle"},
    {"data-uri.gltf", "/buffers/0/uri: data: URI has a non-base64 character at 37"},
    {"version-1.glb", "GLB: header version 1, expected 2 (GLB_INVALID_VERSION)"},
    {"number-1e999.gltf", "invalid JSON"},
    {"translation-1e39.json", "/objects/0/translation/1: 1e+39 is outside the range of a 32-bit float"},
    {"orbit-1e39.json", "/cameraPaths/0/radius: 1e+39 is outside the range of a 32-bit float"},
    {"deep.json", "JSON nested deeper than 256 levels"},
    {"requires-transmission.gltf", "requires the unsupported extension KHR_materials_transmission"},
    {"hdr-missing.json", "sky.hdr: cannot open the environment image"},
    {"hdr-not-radiance.json", "sky.hdr: not a Radiance .hdr image"},
    {"hdr-bad-format.json", "sky.hdr: cannot read the Radiance header"},
    {"hdr-huge.json", "sky.hdr: environment image is 200000x100000, expected 2 to 8192 pixels on a side"},
};

struct Case {
  HostileFile file;
  const char* command;

  friend void PrintTo(const Case& c, std::ostream* out) { *out << c.command << " " << c.file.name; }
};

class HostileCli : public ::testing::TestWithParam<Case> {};

TEST_P(HostileCli, OneLineAndExit1) {
  TempDir dir;
  const auto file = writeHostile(dir, GetParam().file.name);
  const std::string command = GetParam().command;
  const std::string args = command == "inspect" ? "inspect " + file.string()
                                                : "render " + file.string() + " --size 16x16 --frames 1 -o " +
                                                      (dir.path() / "out.png").string();
  const auto r = run(args, dir.path() / "stderr.txt");
  EXPECT_EQ(r.exitCode, 1) << r.err.substr(0, 500);
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "exactly one line: " << r.err.substr(0, 500);
  EXPECT_EQ(r.err.rfind("shadelgraph: error: " + file.string() + ": ", 0), 0u) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find(GetParam().file.expected), std::string::npos) << r.err.substr(0, 500);
  EXPECT_LT(r.err.size(), 1200u) << "a short line: " << r.err.substr(0, 300);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png"));
}

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const HostileFile& file : kFiles)
    for (const char* command : {"inspect", "render"}) cases.push_back({file, command});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Files, HostileCli, ::testing::ValuesIn(allCases()), [](const ::testing::TestParamInfo<Case>& param) {
  std::string name = std::string(param.param.command) + "_" + param.param.file.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

// A 16x16 grid as one TRIANGLE_STRIP (rows stitched with repeated indices)
// and a 32-segment disk as one TRIANGLE_FAN, both with a unique UV chart:
// shaded decoupled, every covered pixel must find its shadels, which holds
// only if the ID-map bake and the mark pass see the triangles that are drawn.
struct Topology {
  const char* name;
  int mode;
  size_t triangles;
};

std::filesystem::path writeTopology(const TempDir& dir, const Topology& topology) {
  std::vector<float> positions, uvs;
  std::vector<uint32_t> indices;
  if (topology.mode == 5) {
    constexpr uint32_t n = 16;
    for (uint32_t j = 0; j <= n; ++j)
      for (uint32_t i = 0; i <= n; ++i) {
        const float x = float(i) / n, y = float(j) / n;
        positions.insert(positions.end(), {2 * x - 1, 2 * y - 1, 0});
        uvs.insert(uvs.end(), {x, 1 - y});
      }
    for (uint32_t j = 0; j < n; ++j) {
      if (!indices.empty()) {  // stitch: repeat the last index and the next first, keeping even parity
        const uint32_t first = (j + 1) * (n + 1);
        indices.insert(indices.end(), {indices.back(), first});
        if (indices.size() % 2 == 1) indices.push_back(first);
      }
      for (uint32_t i = 0; i <= n; ++i) indices.insert(indices.end(), {(j + 1) * (n + 1) + i, j * (n + 1) + i});
    }
  } else {
    constexpr uint32_t segments = 32;
    positions.insert(positions.end(), {0, 0, 0});
    uvs.insert(uvs.end(), {0.5f, 0.5f});
    for (uint32_t k = 0; k <= segments; ++k) {
      const float a = 6.2831853f * float(k) / segments;
      positions.insert(positions.end(), {std::cos(a), std::sin(a), 0});
      uvs.insert(uvs.end(), {0.5f + 0.5f * std::cos(a), 0.5f - 0.5f * std::sin(a)});
    }
    for (uint32_t k = 0; k < segments + 2; ++k) indices.push_back(k);
  }
  std::vector<uint8_t> bin(4 * (positions.size() + uvs.size() + indices.size()));
  std::memcpy(bin.data(), positions.data(), 4 * positions.size());
  std::memcpy(bin.data() + 4 * positions.size(), uvs.data(), 4 * uvs.size());
  std::memcpy(bin.data() + 4 * (positions.size() + uvs.size()), indices.data(), 4 * indices.size());
  dir.write(std::string(topology.name) + ".bin", bin);
  const size_t vertices = positions.size() / 3;
  Json document = Json::parse(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}]})");
  document["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"mode", topology.mode}}}}}};
  document["accessors"] = {
      {{"bufferView", 0}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}, {"min", {-1, -1, 0}}, {"max", {1, 1, 0}}},
      {{"bufferView", 1}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC2"}},
      {{"bufferView", 2}, {"componentType", 5125}, {"count", indices.size()}, {"type", "SCALAR"}}};
  document["bufferViews"] = {{{"buffer", 0}, {"byteLength", 4 * positions.size()}},
                             {{"buffer", 0}, {"byteOffset", 4 * positions.size()}, {"byteLength", 4 * uvs.size()}},
                             {{"buffer", 0}, {"byteOffset", 4 * (positions.size() + uvs.size())}, {"byteLength", 4 * indices.size()}}};
  document["buffers"] = {{{"uri", std::string(topology.name) + ".bin"}, {"byteLength", bin.size()}}};
  return dir.write(std::string(topology.name) + ".gltf", document.dump());
}

class StripsAndFans : public ::testing::TestWithParam<Topology> {};

TEST_P(StripsAndFans, DecoupledHasNoCompositeMisses) {
  TempDir dir;
  const auto file = writeTopology(dir, GetParam());
  const auto stats = dir.path() / "stats.json";
  const auto r = run("render " + file.string() + " --mode decoupled --size 320x240 --frames 1 --stats " + stats.string() +
                           " -o " + (dir.path() / "out.png").string(),
                       dir.path() / "stderr.txt");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(stats);
  const Json json = Json::parse(in);
  EXPECT_EQ(json["triangles"].get<size_t>(), GetParam().triangles);
  EXPECT_EQ(json["objects_decoupled"].get<int>(), 1);
  EXPECT_GT(json["covered_pixels"].get<uint64_t>(), 10000u) << "the shape faces the camera and fills much of the view";
  EXPECT_EQ(json["composite_misses"].get<uint64_t>(), 0u);
  EXPECT_EQ(json["overflow_chunks"].get<uint64_t>(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Files, StripsAndFans,
                         ::testing::Values(Topology{"strip", 5, 16 * 16 * 2}, Topology{"fan", 6, 32}),
                         [](const ::testing::TestParamInfo<Topology>& param) { return std::string(param.param.name); });

}  // namespace
