#include "scene_test_support.hpp"

#include <cstring>
#include <fstream>
#include <random>

#include <unistd.h>

namespace sg::scene::test {

template <class T>
static std::vector<uint8_t> rawBytes(const std::vector<T>& values) {
  std::vector<uint8_t> bytes(values.size() * sizeof(T));
  std::memcpy(bytes.data(), values.data(), bytes.size());  // the test machines are little-endian, as glTF
  return bytes;
}

std::vector<uint8_t> bytesOf(const std::vector<float>& values) { return rawBytes(values); }
std::vector<uint8_t> bytesOf(const std::vector<uint16_t>& values) { return rawBytes(values); }
std::vector<uint8_t> bytesOf(const std::vector<uint32_t>& values) { return rawBytes(values); }

std::vector<uint8_t> concat(std::initializer_list<std::vector<uint8_t>> parts) {
  std::vector<uint8_t> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

std::filesystem::path writeTriangleGltf(const TempDir& dir, const std::string& name, const std::string& nodes,
                                        const std::string& sceneNodes, const std::string& extra) {
  dir.write("triangle.bin", bytesOf(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  return dir.write(name, R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [)" + sceneNodes + R"(]}],
  "nodes": [)" + nodes + R"(],
  "meshes": [{"name": "triangle", "primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}],
  "buffers": [{"uri": "triangle.bin", "byteLength": 36}])" + extra + "\n}\n");
}

}  // namespace sg::scene::test
