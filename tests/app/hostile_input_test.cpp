// Hostile files through the CLI (issue 13): `inspect` and `render` answer each
// with exactly one line `shadelgraph: error: <file>: ...` on stderr and exit
// code 1, never a crash, a flood of text or a silent success. The loader-level
// cases are in tests/unit/scene/hostile_input_test.cpp; docs/hostile-input.md
// has the decisions.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace {

using Json = nlohmann::json;
using sg::test::TempDir;

struct Run {
  int exitCode = -1;
  std::string out;
  std::string err;
};

Run run(const std::string& args, const std::filesystem::path& errFile) {
  const std::string command = std::string(SG_CLI) + " " + args + " 2>" + errFile.string();
  Run r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(errFile, std::ios::binary);
  r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return r;
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

std::vector<uint8_t> glbOf(std::string json, uint32_t version) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::vector<uint8_t> out(20);
  const auto put = [&](size_t at, uint32_t v) { std::memcpy(out.data() + at, &v, 4); };
  std::memcpy(out.data(), "glTF", 4);
  put(4, version);
  put(12, static_cast<uint32_t>(json.size()));
  put(16, 0x4E4F534Au);
  out.insert(out.end(), json.begin(), json.end());
  put(8, static_cast<uint32_t>(out.size()));
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
    {"data-uri.gltf", "buffer"},
    {"version-1.glb", "GLB: header version 1, expected 2 (GLB_INVALID_VERSION)"},
    {"number-1e999.gltf", "invalid JSON"},
    {"translation-1e39.json", "/objects/0/translation/1: 1e+39 is outside the range of a 32-bit float"},
    {"orbit-1e39.json", "/cameraPaths/0/radius: 1e+39 is outside the range of a 32-bit float"},
    {"deep.json", "JSON nested deeper than 256 levels"},
};

struct Case {
  HostileFile file;
  const char* command;
};

class HostileCli : public ::testing::TestWithParam<Case> {};

TEST_P(HostileCli, OneLineAndExit1) {
  TempDir dir;
  const auto file = writeHostile(dir, GetParam().file.name);
  const std::string command = GetParam().command;
  const std::string args = command == "inspect" ? "inspect " + file.string()
                                                : "render " + file.string() + " --size 16x16 --frames 1 -o " +
                                                      (dir.path() / "out.png").string();
  const Run r = run(args, dir.path() / "stderr.txt");
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

}  // namespace
