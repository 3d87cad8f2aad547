// Hostile input (issue 13): files written to crash the loader, to make it
// read or write outside a buffer, to allocate what a number in the file says,
// to wrap an index, or to load silently wrong. Each is rejected with one line
// that names the file and the JSON pointer, as the Khronos glTF-Validator
// would, or loads with a documented warning. docs/hostile-input.md lists the
// decisions.
#include <sys/resource.h>

#include <cstring>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/scene_file.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

using Json = nlohmann::json;
using test::TempDir;
using ::testing::HasSubstr;

// One SceneError message; fails the test if loading succeeds or throws
// anything else. Every message is one line, starts with the file and is short.
template <class Load>
std::string errorOf(const std::filesystem::path& file, Load load) {
  try {
    load(file);
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << "starts with the file: " << message;
    EXPECT_LT(message.size(), 1200u) << "short: " << message.substr(0, 300);
    return message;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "threw something other than SceneError: " << error.what();
    return {};
  }
  ADD_FAILURE() << file << " loaded";
  return {};
}
std::string gltfError(const std::filesystem::path& file) {
  return errorOf(file, [](const std::filesystem::path& f) { loadGltf(f); });
}
std::string sceneFileError(const std::filesystem::path& file) {
  return errorOf(file, [](const std::filesystem::path& f) { loadSceneFile(f); });
}

// The bytes of "hostile.bin": a triangle's positions, its uint16 indices and
// 8 bytes an unused image points at.
std::vector<uint8_t> binBytes() {
  std::vector<uint8_t> bytes = test::concat({test::bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                             test::bytesOf(std::vector<uint16_t>{0, 1, 2, 0})});
  bytes.resize(52, 0x7f);
  return bytes;
}

// A valid file that uses every kind of reference the loader reads: the tests
// change one value each (with a JSON pointer) and expect that value named.
Json validDocument() {
  return Json::parse(R"({
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 2]}],
  "nodes": [{"mesh": 0, "children": [1]}, {"camera": 0, "translation": [0, 0, 3]},
            {"extensions": {"KHR_lights_punctual": {"light": 0}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1]}}],
  "textures": [{"source": 0, "sampler": 0}], "samplers": [{}],
  "images": [{"bufferView": 2, "mimeType": "image/png"}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                  {"buffer": 0, "byteOffset": 44, "byteLength": 8}],
  "buffers": [{"uri": "hostile.bin", "byteLength": 52}],
  "extensionsUsed": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 5}]}}})");
}

std::filesystem::path writeGltf(const TempDir& dir, const Json& document, const std::string& name = "hostile.gltf") {
  dir.write("hostile.bin", binBytes());
  return dir.write(name, document.dump());
}

// A .glb of `json` (padded) and, when given, a BIN chunk.
std::vector<uint8_t> glbOf(std::string json, const std::vector<uint8_t>& bin) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  std::vector<uint8_t> out;
  const auto u32 = [&](uint32_t v) {
    const auto* p = reinterpret_cast<const uint8_t*>(&v);
    out.insert(out.end(), p, p + 4);
  };
  out.insert(out.end(), {'g', 'l', 'T', 'F'});
  u32(2);
  u32(static_cast<uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
  u32(static_cast<uint32_t>(json.size()));
  u32(0x4E4F534Au);
  out.insert(out.end(), json.begin(), json.end());
  if (bin.empty()) return out;
  u32(static_cast<uint32_t>(bin.size()));
  u32(0x004E4942u);
  out.insert(out.end(), bin.begin(), bin.end());
  return out;
}

// `document` as a .glb with hostile.bin as its BIN chunk.
std::vector<uint8_t> glbBytes(Json document) {
  document["buffers"][0].erase("uri");
  return glbOf(document.dump(), binBytes());
}

TEST(HostileInput, TheValidDocumentLoads) {
  TempDir dir;
  const Scene scene = loadGltf(writeGltf(dir, validDocument()));
  EXPECT_EQ(scene.instances.size(), 1u);
  EXPECT_EQ(scene.cameras.size(), 1u);
  EXPECT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.meshes.at(0).triangleCount(), 1u);
  const Scene binary = loadGltf(dir.write("hostile.glb", glbBytes(validDocument())));
  EXPECT_EQ(binary.meshes.at(0).triangleCount(), 1u);
}

// One value changed; the message must name `expected` (the JSON pointer the
// validator names, and what is wrong).
struct Mutation {
  const char* name;
  const char* pointer;
  const char* value;  // JSON text
  const char* expected;

  friend void PrintTo(const Mutation& m, std::ostream* out) { *out << m.name; }
};

std::string testName(const ::testing::TestParamInfo<Mutation>& info) { return info.param.name; }

TEST(HostileInput, AValueOf2To32IsNotIndex0) {
  // The case from the issue: tinygltf keeps indices in int, so 2^32 became mesh 0.
  TempDir dir;
  Json document = validDocument();
  document["nodes"][0]["mesh"] = 4294967296ull;
  EXPECT_THAT(gltfError(writeGltf(dir, document)), HasSubstr("/nodes/0/mesh: mesh 4294967296 does not exist (the file has 1)"));
}

// UNRESOLVED_REFERENCE: every index, at 2^32 (wraps to 0 in int) or 2^31
// (negative in int), names its JSON pointer.
const Mutation kReferences[] = {
    {"Scene", "/scene", "4294967296", "/scene: scene 4294967296 does not exist"},
    {"SceneNode", "/scenes/0/nodes/0", "4294967296", "/scenes/0/nodes/0: node 4294967296 does not exist"},
    {"NodeMesh", "/nodes/0/mesh", "2147483648", "/nodes/0/mesh: mesh 2147483648 does not exist"},
    {"NodeCamera", "/nodes/1/camera", "4294967296", "/nodes/1/camera: camera 4294967296 does not exist"},
    {"NodeChild", "/nodes/0/children/0", "4294967297", "/nodes/0/children/0: node 4294967297 does not exist"},
    {"NodeSkin", "/nodes/0/skin", "4294967296", "/nodes/0/skin: skin 4294967296 does not exist (the file has 0)"},
    {"NodeLight", "/nodes/2/extensions/KHR_lights_punctual/light", "4294967296",
     "/nodes/2/extensions/KHR_lights_punctual/light: light 4294967296 does not exist (the file has 1)"},
    {"PrimitiveAttribute", "/meshes/0/primitives/0/attributes/POSITION", "4294967296",
     "/meshes/0/primitives/0/attributes/POSITION: accessor 4294967296 does not exist"},
    {"PrimitiveIndices", "/meshes/0/primitives/0/indices", "4294967297", "/meshes/0/primitives/0/indices: accessor"},
    {"PrimitiveMaterial", "/meshes/0/primitives/0/material", "4294967296",
     "/meshes/0/primitives/0/material: material 4294967296 does not exist"},
    {"AccessorBufferView", "/accessors/0/bufferView", "4294967296", "/accessors/0/bufferView: bufferView 4294967296"},
    {"BufferViewBuffer", "/bufferViews/0/buffer", "4294967296", "/bufferViews/0/buffer: buffer 4294967296 does not exist"},
    {"TextureSource", "/textures/0/source", "4294967296", "/textures/0/source: image 4294967296 does not exist"},
    {"TextureSampler", "/textures/0/sampler", "4294967296", "/textures/0/sampler: sampler 4294967296 does not exist"},
    {"ImageBufferView", "/images/0/bufferView", "3", "/images/0/bufferView: bufferView 3 does not exist (the file has 3)"},
    {"MaterialTexture", "/materials/0/pbrMetallicRoughness/baseColorTexture", R"({"index": 4294967296})",
     "/materials/0/pbrMetallicRoughness/baseColorTexture/index: texture 4294967296 does not exist"},
    {"NormalTexture", "/materials/0/normalTexture", R"({"index": 1})",
     "/materials/0/normalTexture/index: texture 1 does not exist (the file has 1)"},
    {"SkinJoint", "/skins", R"([{"joints": [4294967296]}])", "/skins/0/joints/0: node 4294967296 does not exist"},
    {"AnimationSampler", "/animations", R"([{"channels": [{"sampler": 0, "target": {"node": 0, "path": "scale"}}], "samplers": []}])",
     "/animations/0/channels/0/sampler: animation sampler 0 does not exist (the file has 0)"},
};

class UnresolvedReference : public ::testing::TestWithParam<Mutation> {};

TEST_P(UnresolvedReference, NamesThePointer) {
  TempDir dir;
  Json document = validDocument();
  document[Json::json_pointer(GetParam().pointer)] = Json::parse(GetParam().value);
  EXPECT_THAT(gltfError(writeGltf(dir, document)), HasSubstr(GetParam().expected));
}

INSTANTIATE_TEST_SUITE_P(Files, UnresolvedReference, ::testing::ValuesIn(kReferences), testName);

// Byte ranges: offsets and counts near 2^64 must not wrap a bounds check,
// and no count may allocate more than the bytes behind it.
const Mutation kRanges[] = {
    // Wrapped the check in copyElements and read megabytes before the buffer.
    {"ByteOffsetNear2To64", "/accessors/0/byteOffset", "18446744073709551600",
     "/accessors/0/byteOffset: 18446744073709551600 is past the end of its bufferView (36 bytes) (ACCESSOR_TOO_LONG)"},
    {"ByteOffsetPastView", "/accessors/0/byteOffset", "4", "/accessors/0: 3 elements of 12 bytes from offset 4 do not fit"},
    // The 1 KB file that zero-filled 8 GiB before its error.
    {"IndexCount2To32", "/accessors/1/count", "4294967295", "/accessors/1: 4294967295 elements of 2 bytes"},
    {"CountOverflowsTheProduct", "/accessors/0/count", "1537228672809129302", "/accessors/0: 1537228672809129302 elements"},
    {"StrideRunsPastTheView", "/bufferViews/0/byteStride", "252", "/accessors/0: 3 elements of 12 bytes, 252 apart,"},
    {"SmallStride", "/bufferViews/0/byteStride", "8", "/accessors/0: its bufferView's byteStride 8 is smaller"},
    {"BufferViewTooLong", "/bufferViews/1/byteOffset", "18446744073709551615",
     "/bufferViews/1: bytes at offset 18446744073709551615, length 6 do not fit buffer 0's byteLength 52"},
    // A sparse accessor without a bufferView: nothing backs its zeros.
    {"UnbackedSparseCount2To62", "/accessors/0",
     R"({"componentType": 5126, "count": 4611686018427387904, "type": "VEC3", "sparse": {"count": 1,
         "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}}})",
     "/accessors/0/count: 4611686018427387904 elements without a bufferView (at most 16777216"},
    {"SparseCountAboveCount", "/accessors/0/sparse",
     R"({"count": 4, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}})",
     "/accessors/0/sparse/count: 4 exceeds the accessor's count 3"},
    // Read 2-288 bytes before the buffer: tinygltf keeps sparse offsets in int.
    {"SparseOffsetWrapsInt", "/accessors/0/sparse",
     R"({"count": 1, "indices": {"bufferView": 1, "byteOffset": 4294967294, "componentType": 5123},
         "values": {"bufferView": 0}})",
     "/accessors/0/sparse/indices/byteOffset: expected an integer in [0, 2147483647], got the number 4294967294"},
    {"SparseOffsetPastTheView", "/accessors/0/sparse",
     R"({"count": 1, "indices": {"bufferView": 1, "byteOffset": 1000, "componentType": 5123}, "values": {"bufferView": 0}})",
     "/accessors/0/sparse/indices/byteOffset: 1000 is past the end of its bufferView (6 bytes)"},
    {"SparseValuesTooLong", "/accessors/0/sparse",
     R"({"count": 3, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0, "byteOffset": 12}})",
     "/accessors/0/sparse/values: 3 elements of 12 bytes from offset 12 do not fit"},
    {"SparseIndicesCount2To31", "/accessors/0",
     R"({"componentType": 5126, "count": 3000000000, "type": "VEC3", "sparse": {"count": 2147483648,
         "indices": {"bufferView": 1, "componentType": 5125}, "values": {"bufferView": 0}}})",
     "/accessors/0/sparse/count: expected an integer in [0, 2147483647], got the number 2147483648"},
};

class ByteRange : public ::testing::TestWithParam<Mutation> {};

TEST_P(ByteRange, IsCheckedWithoutWrapping) {
  TempDir dir;
  Json document = validDocument();
  document[Json::json_pointer(GetParam().pointer)] = Json::parse(GetParam().value);
  EXPECT_THAT(gltfError(writeGltf(dir, document)), HasSubstr(GetParam().expected));
}

INSTANTIATE_TEST_SUITE_P(Files, ByteRange, ::testing::ValuesIn(kRanges), testName);

// The 2^32-1 index count: its error comes before any allocation. Peak memory
// (not time) is what the bug consumed: 8 GiB.
TEST(HostileInput, ACountAllocatesNothingBeforeItIsChecked) {
  TempDir dir;
  Json document = validDocument();
  document["accessors"][1]["count"] = 4294967295u;
  const auto file = writeGltf(dir, document);
  rusage before{};
  getrusage(RUSAGE_SELF, &before);
  EXPECT_THAT(gltfError(file), HasSubstr("ACCESSOR_TOO_LONG"));
  rusage after{};
  getrusage(RUSAGE_SELF, &after);
  EXPECT_LT(after.ru_maxrss - before.ru_maxrss, 256 * 1024) << "peak RSS grew by " << (after.ru_maxrss - before.ru_maxrss) << " KiB";
}

// Other validator classes that change what is drawn.
const Mutation kValidatorClasses[] = {
    {"AccessorCountZero", "/accessors/0/count", "0", "/accessors/0/count: expected an integer >= 1, got the number 0"},
    {"SparseCountZero", "/accessors/0/sparse",
     R"({"count": 0, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}})",
     "/accessors/0/sparse/count: expected an integer >= 1"},
    {"BufferViewLengthZero", "/bufferViews/2/byteLength", "0", "/bufferViews/2/byteLength: expected an integer >= 1"},
    // tinygltf drops an optional 4.0 (reading from 0) and rejects a required one.
    {"CountWrittenAsFloat", "/accessors/0/count", "3.0",
     "/accessors/0/count: expected an integer >= 0 written without a fraction, got the number 3.0"},
    {"OffsetWrittenAsFloat", "/bufferViews/1/byteOffset", "36.0", "/bufferViews/1/byteOffset: expected an integer >= 0 written"},
    // tinygltf keeps these in int: 2^32 + 1 would be TEXCOORD_1, 2^32 + 9729 a valid LINEAR filter.
    {"TexCoord2To32Plus1", "/materials/0/normalTexture", R"({"index": 0, "texCoord": 4294967297})",
     "/materials/0/normalTexture/texCoord: expected an integer in [0, 2147483647], got the number 4294967297"},
    {"SamplerEnum2To32", "/samplers/0/magFilter", "4294977025", "/samplers/0/magFilter: expected an integer in [0, 2147483647]"},
    {"PrimitiveMode2To32", "/meshes/0/primitives/0/mode", "4294967300", "/meshes/0/primitives/0/mode: expected an integer in"},
    {"MatrixWithTrs", "/nodes/1/matrix", "[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,3,1]", "/nodes/1: has both a matrix and translation"},
    {"ShearedMatrix", "/nodes/0/matrix", "[1,0,0,0, 1,1,0,0, 0,0,1,0, 0,0,0,1]", "/nodes/0/matrix: is not decomposable"},
    {"ProjectiveMatrix", "/nodes/0/matrix", "[1,0,0,0.5, 0,1,0,0, 0,0,1,0, 0,0,0,1]", "last row is not 0, 0, 0, 1"},
    // Material factors outside [0, 1] (VALUE_NOT_IN_RANGE) are no material.
    {"BaseColorAboveOne", "/materials/0/pbrMetallicRoughness/baseColorFactor", "[1, 3, 1, 1]",
     "/materials/0/pbrMetallicRoughness/baseColorFactor/1: expected a number in [0, 1], got the number 3"},
    {"MetallicNegative", "/materials/0/pbrMetallicRoughness/metallicFactor", "-1",
     "/materials/0/pbrMetallicRoughness/metallicFactor: expected a number in [0, 1], got the number -1"},
    {"RoughnessAboveOne", "/materials/0/pbrMetallicRoughness/roughnessFactor", "1.5", "roughnessFactor: expected a number in [0, 1]"},
    {"EmissiveAboveOne", "/materials/0/emissiveFactor", "[0, 0, 2]", "/materials/0/emissiveFactor/2: expected a number in [0, 1]"},
    {"OcclusionStrengthNegative", "/materials/0/occlusionTexture", R"({"index": 0, "strength": -0.5})",
     "/materials/0/occlusionTexture/strength: expected a number in [0, 1]"},
    {"AlphaCutoffNegative", "/materials/0/alphaCutoff", "-0.5", "/materials/0/alphaCutoff: expected a number >= 0"},
    // UNKNOWN_ASSET_MAJOR_VERSION, and a minVersion this loader cannot meet.
    {"AssetVersion3", "/asset/version", R"("3.0")", "/asset/version: expected a glTF 2.x version (this loader reads glTF 2.0), got the string \"3.0\""},
    {"AssetVersionMalformed", "/asset/version", R"("2")", "/asset/version: expected a version written <major>.<minor>"},
    {"AssetMinVersion21", "/asset/minVersion", R"("2.1")", "/asset/minVersion: expected 2.0 (this loader reads glTF 2.0)"},
};

class ValidatorClass : public ::testing::TestWithParam<Mutation> {};

TEST_P(ValidatorClass, IsRejected) {
  TempDir dir;
  Json document = validDocument();
  document[Json::json_pointer(GetParam().pointer)] = Json::parse(GetParam().value);
  EXPECT_THAT(gltfError(writeGltf(dir, document)), HasSubstr(GetParam().expected));
}

INSTANTIATE_TEST_SUITE_P(Files, ValidatorClass, ::testing::ValuesIn(kValidatorClasses), testName);

// ACCESSOR_INDEX_OOB: an index value >= the vertex count, named with its accessor.
TEST(HostileInput, IndexValueOutOfRange) {
  TempDir dir;
  Json document = validDocument();
  std::vector<uint8_t> bin = binBytes();
  bin[38] = 3;  // indices {0, 3, 2}: the triangle has 3 vertices
  document["buffers"][0]["uri"] = "oob.bin";
  dir.write("oob.bin", bin);
  EXPECT_THAT(gltfError(writeGltf(dir, document)),
              HasSubstr("index 3 (indices[1]) is out of range: the primitive has 3 vertices (/accessors/1, ACCESSOR_INDEX_OOB)"));
}

// ACCESSOR_MIN/MAX_MISMATCH: a warning (bounds are computed from the data).
TEST(HostileInput, MinMaxMismatchIsAWarning) {
  TempDir dir;
  Json document = validDocument();
  document["accessors"][0]["max"] = {1, 5, 0};
  const Scene scene = loadGltf(writeGltf(dir, document));
  EXPECT_THAT(::testing::PrintToString(scene.warnings), HasSubstr("accessor min/max differ from the data"));
  EXPECT_THAT(::testing::PrintToString(scene.warnings), HasSubstr("/accessors/0/max/1"));
  EXPECT_EQ(scene.meshes.at(0).bounds.max.y, 1.0f) << "bounds from the data, not from max";
}

// Numbers finite as double but not as float, and finite inputs with
// non-finite results.
const Mutation kFloats[] = {
    {"Translation1e39", "/nodes/1/translation/2", "1e39", "/nodes/1/translation/2: expected a number within the range of a 32-bit float, got the number 1e+39"},
    {"LightIntensity1e39", "/extensions/KHR_lights_punctual/lights/0/intensity", "1e39",
     "/extensions/KHR_lights_punctual/lights/0/intensity: expected a number within the range of a 32-bit float"},
    {"TextureTransformScale1e300", "/materials/0/pbrMetallicRoughness/baseColorTexture",
     R"({"index": 0, "extensions": {"KHR_texture_transform": {"scale": [1e300, 1]}}})",
     "baseColorTexture/extensions/KHR_texture_transform/scale/0: expected a number within the range of a 32-bit float"},
    {"TextureTransformScale1e30", "/materials/0/pbrMetallicRoughness/baseColorTexture",
     R"({"index": 0, "extensions": {"KHR_texture_transform": {"scale": [1, 1e30]}}})",
     "KHR_texture_transform/scale/1: 1e+30 is beyond +-1e18"},
    {"Translation1e30", "/nodes/1/translation/0", "1e30", "/nodes/1/translation/0: 1e+30 is beyond +-1e18"},
    {"Zfar1e308", "/cameras/0/perspective/zfar", "1e308", "/cameras/0/perspective/zfar: expected a number within the range"},
    {"ZfarTimesZnearOverflows", "/cameras/0/perspective", R"({"yfov": 0.8, "znear": 1e10, "zfar": 3e38})",
     "camera 0: its znear, zfar, yfov, xmag, ymag give a non-finite projection matrix"},
    {"YfovPi", "/cameras/0/perspective/yfov", "3.1415927", "camera 0: perspective yfov 3.141593 must be below pi"},
    {"WorldOverflows", "/nodes",
     R"([{"mesh": 0, "children": [1], "scale": [1e30, 1e30, 1e30]}, {"camera": 0, "scale": [1e30, 1e30, 1e30]}, {}])",
     "node 1: world transform (its own times its parents') is not finite"},
};

class FloatRange : public ::testing::TestWithParam<Mutation> {};

TEST_P(FloatRange, IsRejectedNamingTheField) {
  TempDir dir;
  Json document = validDocument();
  document[Json::json_pointer(GetParam().pointer)] = Json::parse(GetParam().value);
  EXPECT_THAT(gltfError(writeGltf(dir, document)), HasSubstr(GetParam().expected));
}

INSTANTIATE_TEST_SUITE_P(Files, FloatRange, ::testing::ValuesIn(kFloats), testName);

TEST(HostileInput, Number1e999NamesTheFile) {
  TempDir dir;
  std::string text = validDocument().dump();
  text.replace(text.find("\"intensity\":5"), 13, "\"intensity\":1e999");
  const std::string message = gltfError(dir.write("big.gltf", text));
  EXPECT_THAT(message, HasSubstr("invalid JSON"));
  EXPECT_THAT(message, HasSubstr("1e999"));
}

// Nesting deep enough to overflow a recursive parser's stack, in extras, in
// an extension, in a .glb and in a scene file.
std::string nested(size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

TEST(HostileInput, DeepNestingIsRejectedBeforeParsing) {
  TempDir dir;
  std::string text = validDocument().dump();
  const std::string deep = nested(16000);
  std::string inExtras = text;
  inExtras.insert(inExtras.find("\"mesh\":0"), "\"extras\":" + deep + ",");
  EXPECT_THAT(gltfError(dir.write("extras.gltf", inExtras)), HasSubstr("JSON nested deeper than 256 levels"));
  std::string inExtension = text;
  inExtension.insert(inExtension.find("\"mesh\":0"), "\"extensions\":{\"EXT_x\":{\"a\":" + deep + "}},");
  EXPECT_THAT(gltfError(dir.write("extension.gltf", inExtension)), HasSubstr("JSON nested deeper than 256 levels"));

  Json document = validDocument();
  document["nodes"][0]["extras"] = Json::parse(nested(200));  // deep, but within the limit
  EXPECT_NO_THROW(loadGltf(writeGltf(dir, document, "fine.gltf")));
  std::string inGlb = text;
  inGlb.insert(inGlb.find("\"mesh\":0"), "\"extras\":" + deep + ",");
  EXPECT_THAT(gltfError(dir.write("deep.glb", glbOf(inGlb, {}))), HasSubstr("JSON nested deeper than 256 levels"));
  EXPECT_THAT(sceneFileError(dir.write("deep.json", "{\"objects\": [], \"lights\": " + deep + "}")),
              HasSubstr("JSON nested deeper than 256 levels"));
}

TEST(HostileInput, BracketsInsideStringsDoNotCount) {
  TempDir dir;
  Json document = validDocument();
  document["nodes"][0]["name"] = std::string(5000, '[') + "\\\"" + std::string(5000, '{');
  document["nodes"][0]["extras"] = {{"note", "a \" quote and ]]]] closing brackets"}};
  EXPECT_NO_THROW(loadGltf(writeGltf(dir, document)));
}

// GLB containers that lie about themselves.
struct GlbCase {
  const char* name;
  size_t offset;    // of the uint32 to overwrite, or SIZE_MAX to append 4 bytes
  uint32_t value;
  const char* expected;
};

const GlbCase kGlbCases[] = {
    {"Version1", 4, 1, "GLB: header version 1, expected 2 (GLB_INVALID_VERSION)"},
    {"LengthTooLarge", 8, 100000, "GLB: header length 100000 differs from the file's"},
    {"LengthTooSmall", 8, 40, "GLB: header length 40 differs from the file's"},
    {"JsonChunkTooBig", 12, 0x7ffffff0u, "GLB chunk 0: length 2147483632 runs past the end of the file"},
    {"JsonChunkUnaligned", 12, 0, "is not a multiple of 4 (GLB_CHUNK_LENGTH_UNALIGNED)"},  // length - 1, see the test
    {"FirstChunkIsBin", 16, 0x004E4942u, "GLB chunk 0: the first chunk must be JSON"},
    {"TrailingBytes", SIZE_MAX, 0, "bytes left for an 8-byte chunk header"},
};

class LyingGlb : public ::testing::TestWithParam<GlbCase> {};

TEST_P(LyingGlb, IsRejected) {
  TempDir dir;
  std::vector<uint8_t> glb = glbBytes(validDocument());
  const GlbCase& c = GetParam();
  if (c.offset == SIZE_MAX) {
    glb.insert(glb.end(), {0, 0, 0, 0});
    const auto length = static_cast<uint32_t>(glb.size());
    std::memcpy(glb.data() + 8, &length, 4);
  } else if (std::string(c.name) == "JsonChunkUnaligned") {
    uint32_t length = 0;
    std::memcpy(&length, glb.data() + 12, 4);
    length -= 1;
    std::memcpy(glb.data() + 12, &length, 4);
  } else {
    std::memcpy(glb.data() + c.offset, &c.value, 4);
  }
  EXPECT_THAT(gltfError(dir.write("lying.glb", glb)), HasSubstr(c.expected));
}

INSTANTIATE_TEST_SUITE_P(Files, LyingGlb, ::testing::ValuesIn(kGlbCases),
                         [](const ::testing::TestParamInfo<GlbCase>& param) { return std::string(param.param.name); });

TEST(HostileInput, GlbBinChunkPastTheEnd) {
  TempDir dir;
  std::vector<uint8_t> glb = glbBytes(validDocument());
  uint32_t jsonLength = 0;
  std::memcpy(&jsonLength, glb.data() + 12, 4);
  const uint32_t binLength = 1000;
  std::memcpy(glb.data() + 20 + jsonLength, &binLength, 4);
  EXPECT_THAT(gltfError(dir.write("bin.glb", glb)), HasSubstr("GLB chunk 1: length 1000 runs past the end of the file (52 bytes left) (GLB_CHUNK_TOO_BIG)"));
}

// What an error quotes from the file is capped.
TEST(HostileInput, ErrorsQuoteAtMostAFewHundredCharacters) {
  TempDir dir;
  {
    Json document = validDocument();
    document["buffers"][0]["uri"] = "data:application/octet-stream;base64," + std::string(68000, '!');
    const std::string message = gltfError(writeGltf(dir, document));
    EXPECT_THAT(message, HasSubstr("/buffers/0/uri: data: URI has a non-base64 character at 37"));
    EXPECT_LT(message.size(), 300u) << message.substr(0, 200);
  }
  {
    Json document = validDocument();
    Json& nodes = document["nodes"];
    nodes = Json::array();
    for (int i = 0; i < 50000; ++i) nodes.push_back({{"children", {(i + 1) % 50000}}});
    document["scenes"][0]["nodes"] = {0};
    const std::string message = gltfError(writeGltf(dir, document));
    EXPECT_THAT(message, HasSubstr("node hierarchy has a cycle"));
    EXPECT_THAT(message, HasSubstr("more)"));
    EXPECT_LT(message.size(), 400u);
  }
  {
    Json document = validDocument();
    document["nodes"][1]["name"] = std::string(100000, 'x');
    document["asset"]["generator"] = std::string(100000, 'y');
    document["asset"]["version"] = std::string(100000, 'z');
    document["nodes"][0]["mesh"] = std::string(100000, 'w');
    const std::string message = gltfError(writeGltf(dir, document));
    EXPECT_THAT(message, HasSubstr("/asset/version: expected a version written <major>.<minor>, got the string \"zzz"));
    EXPECT_LT(message.size(), 400u);
    document["asset"]["version"] = "2.0";
    const std::string meshMessage = gltfError(writeGltf(dir, document));
    EXPECT_THAT(meshMessage, HasSubstr("/nodes/0/mesh: expected an integer >= 0, got the string \"www"));
    EXPECT_LT(meshMessage.size(), 400u);
  }
}

// An accessor without a bufferView may hold up to 2^24 zeros; referenced by
// many primitives, its reads would multiply the memory: capped.
TEST(HostileInput, SharedAccessorsCannotMultiplyMemory) {
  TempDir dir;
  Json document = validDocument();
  document["accessors"].push_back(Json::parse(R"({"componentType": 5126, "count": 1048576, "type": "VEC3",
      "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123}, "values": {"bufferView": 0}}})"));
  Json& primitives = document["meshes"][0]["primitives"];
  primitives = Json::array();
  for (int i = 0; i < 64; ++i) primitives.push_back({{"attributes", {{"POSITION", 2}}}});
  EXPECT_THAT(gltfError(writeGltf(dir, document)), HasSubstr("is one accessor shared by thousands of primitives?"));
}

// A PNG header claiming 20000 x 10000 pixels (800 MB of RGBA; stb_image's
// own limit is 1 GiB) in a 33-byte image: rejected from the header, before
// stb_image allocates.
TEST(HostileInput, ImageSizeIsCheckedBeforeDecoding) {
  TempDir dir;
  std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                              0, 0, 0x4e, 0x20, 0, 0, 0x27, 0x10, 8, 6, 0, 0, 0, 0, 0, 0, 0};
  dir.write("huge.png", png);
  Json document = validDocument();
  document["images"][0] = {{"uri", "huge.png"}};
  document["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  const std::string message = gltfError(writeGltf(dir, document));
  EXPECT_THAT(message, HasSubstr("image 'huge.png' (image 0), used by material 0 baseColorTexture, cannot be decoded: "
                                 "image is 20000x10000, more than 16384 pixels on a side"));
}

TEST(HostileInput, ManyWarningsAreSummarized) {
  TempDir dir;
  Json document = validDocument();
  document["meshes"][0]["primitives"] = Json::array();
  for (int i = 0; i < 100; ++i)
    document["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"mode", 0}}}}});
  const Scene scene = loadGltf(writeGltf(dir, document));
  ASSERT_EQ(scene.warnings.size(), 21u);
  EXPECT_THAT(scene.warnings.back(), ::testing::MatchesRegex("and [0-9]+ more warnings"));
}

// Scene files: the same classes.
std::filesystem::path writeSceneFile(const TempDir& dir, const std::string& body) {
  writeGltf(dir, validDocument());
  return dir.write("scene.json", body);
}

struct SceneCase {
  const char* name;
  const char* body;
  const char* expected;
};

const SceneCase kSceneCases[] = {
    {"Translation1e39", R"({"objects": [{"gltf": "hostile.gltf", "translation": [0, 1e39, 0]}]})",
     "/objects/0/translation/1: 1e+39 is outside the range of a 32-bit float"},
    {"Translation1e20", R"({"objects": [{"gltf": "hostile.gltf", "translation": [1e20, 0, 0]}]})",
     "/objects/0/translation/0: 1e+20 is beyond +-1e18"},
    {"Scale1e39", R"({"objects": [{"gltf": "hostile.gltf", "scale": 1e39}]})", "/objects/0/scale: 1e+39 is outside"},
    {"LightIntensity1e39", R"({"objects": [], "lights": [{"type": "point", "intensity": 1e39}]})",
     "/lights/0/intensity: 1e+39 is outside the range of a 32-bit float"},
    {"OrbitRadius1e39", R"({"objects": [], "cameraPaths": [{"type": "orbit", "radius": 1e39}]})",
     "/cameraPaths/0/radius: 1e+39 is outside"},
    {"OrbitRadius1e30", R"({"objects": [], "cameraPaths": [{"type": "orbit", "radius": 1e30}]})",
     "/cameraPaths/0/radius: 1e+30 is beyond +-1e18"},
    {"KeyPosition", R"({"objects": [], "cameraPaths": [{"type": "keys", "keys": [{"t": 0, "position": [0, 0, 3e38], "target": [0, 0, 0]}]}]})",
     "/cameraPaths/0/keys/0/position/2: 3e+38 is beyond +-1e18"},
    {"Number1e999", R"({"objects": [], "lights": [{"type": "point", "intensity": 1e999}]})", "invalid JSON"},
    // Finite floats whose squared length overflows: normalizing gave a zero direction or rotation.
    {"Direction3e38", R"({"objects": [], "lights": [{"type": "directional", "direction": [3e38, 0, 0]}]})",
     "/lights/0/direction/0: 3e+38 is beyond +-1e18"},
    {"Rotation3e38", R"({"objects": [{"gltf": "hostile.gltf", "rotation": [0, 3e38, 0, 1]}]})",
     "/objects/0/rotation/1: 3e+38 is beyond +-1e18"},
    {"HostileGltf", R"({"objects": [{"gltf": "bad.gltf"}]})", "/objects/0/gltf: "},
    {"LongUnknownKey", R"({"objects": [{"gltf": "hostile.gltf", "LONGKEY": 1}]})", "unknown property 'kkkkk"},
};

class HostileSceneFile : public ::testing::TestWithParam<SceneCase> {};

TEST_P(HostileSceneFile, IsRejectedNamingTheField) {
  TempDir dir;
  Json bad = validDocument();
  bad["nodes"][0]["mesh"] = 4294967296ull;
  dir.write("bad.gltf", bad.dump());
  std::string body = GetParam().body;
  if (const size_t at = body.find("LONGKEY"); at != std::string::npos) body.replace(at, 7, std::string(50000, 'k'));
  const std::string message = sceneFileError(writeSceneFile(dir, body));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
}

INSTANTIATE_TEST_SUITE_P(Files, HostileSceneFile, ::testing::ValuesIn(kSceneCases),
                         [](const ::testing::TestParamInfo<SceneCase>& param) { return std::string(param.param.name); });

}  // namespace
}  // namespace sg::scene
