// Triangle strips and fans from a glTF file (written by the test: a 16x16
// grid as one TRIANGLE_STRIP with degenerate joins, a disc as a
// TRIANGLE_FAN, one textured material), validation on: they reach the ID-map
// bake and the mark pass as the triangles they are, so decoupled has no
// composite misses and agrees with forward.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/image/png.hpp>
#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/procedural_textures.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"
#include "test_support.hpp"

namespace sg::test {
namespace {

struct Vertex {
  glm::vec3 position, normal;
  glm::vec2 uv;
};

// Appends raw bytes of `values` to `bin`, 4-byte aligned; returns the offset.
template <class T>
size_t append(std::vector<uint8_t>& bin, const std::vector<T>& values) {
  while (bin.size() % 4) bin.push_back(0);
  const size_t offset = bin.size();
  bin.resize(offset + values.size() * sizeof(T));
  std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
  return offset;
}

constexpr int kGrid = 16, kRim = 48;

// Grid rows a_i (far) / b_i (near) as one strip: a0 b0 a1 b1 ... an bn, then
// bn a'0 (two repeated corners: degenerate triangles, parity kept) and the next row.
void gridStrip(std::vector<Vertex>& vertices, std::vector<uint32_t>& strip) {
  for (int j = 0; j <= kGrid; ++j)
    for (int i = 0; i <= kGrid; ++i) {
      const float u = float(i) / kGrid, v = float(j) / kGrid;
      vertices.push_back({{u * 2.0f - 1.0f, 0.0f, v * 2.0f - 1.0f}, {0.0f, 1.0f, 0.0f}, {u, v}});
    }
  for (int j = 0; j < kGrid; ++j) {
    if (j > 0) {
      strip.push_back(strip.back());
      strip.push_back(uint32_t(j * (kGrid + 1)));
    }
    for (int i = 0; i <= kGrid; ++i) {
      strip.push_back(uint32_t(j * (kGrid + 1) + i));
      strip.push_back(uint32_t((j + 1) * (kGrid + 1) + i));
    }
  }
}

// Centre, then the rim clockwise seen from +Y (fan triangle i is {v[i+1], v[i+2], v[0]}: counter-clockwise).
void discFan(std::vector<Vertex>& vertices, std::vector<uint32_t>& fan) {
  vertices.push_back({{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.5f, 0.5f}});
  fan.push_back(0);
  for (int i = 0; i < kRim; ++i) {
    const float a = -float(i) / kRim * 2.0f * std::numbers::pi_v<float>;
    vertices.push_back({{std::cos(a), 0.0f, std::sin(a)}, {0.0f, 1.0f, 0.0f},
                        {0.5f + 0.49f * std::cos(a), 0.5f + 0.49f * std::sin(a)}});
    fan.push_back(uint32_t(i + 1));
  }
  fan.push_back(1);  // close the disc
}

std::string primitiveJson(size_t firstAccessor, int mode) {
  return "{\"attributes\":{\"POSITION\":" + std::to_string(firstAccessor) +
         ",\"NORMAL\":" + std::to_string(firstAccessor + 1) + ",\"TEXCOORD_0\":" + std::to_string(firstAccessor + 2) +
         "},\"indices\":" + std::to_string(firstAccessor + 3) + ",\"mode\":" + std::to_string(mode) +
         ",\"material\":0}";
}

// Writes the file; returns its path.
std::filesystem::path writeStripsAndFans(const TempDir& dir) {
  const scene::Texture tiles = scene::makeTilesColor(128, 8);
  image::writePng(dir.path() / "tiles.png", tiles.width, tiles.height, tiles.pixels.data());
  std::vector<uint8_t> bin;
  std::string views, accessors;
  size_t viewCount = 0;
  const auto addMesh = [&](const std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices) {
    const size_t first = viewCount;
    const size_t vOffset = append(bin, vertices), iOffset = append(bin, indices);
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const auto& v : vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
    views += (viewCount ? "," : "") + std::string("{\"buffer\":0,\"byteOffset\":") + std::to_string(vOffset) +
             ",\"byteLength\":" + std::to_string(vertices.size() * sizeof(Vertex)) +
             ",\"byteStride\":" + std::to_string(sizeof(Vertex)) + "}";
    views += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(iOffset) +
             ",\"byteLength\":" + std::to_string(indices.size() * 4) + "}";
    char minmax[160];
    std::snprintf(minmax, sizeof minmax, "\"min\":[%g,%g,%g],\"max\":[%g,%g,%g]", double(lo.x), double(lo.y),
                  double(lo.z), double(hi.x), double(hi.y), double(hi.z));
    const std::string n = std::to_string(vertices.size()), vv = std::to_string(first);
    accessors += (first ? "," : "") + std::string("{\"bufferView\":") + vv + ",\"byteOffset\":0,\"componentType\":5126,\"count\":" +
                 n + ",\"type\":\"VEC3\"," + minmax + "}";
    accessors += ",{\"bufferView\":" + vv + ",\"byteOffset\":12,\"componentType\":5126,\"count\":" + n +
                 ",\"type\":\"VEC3\"}";
    accessors += ",{\"bufferView\":" + vv + ",\"byteOffset\":24,\"componentType\":5126,\"count\":" + n +
                 ",\"type\":\"VEC2\"}";
    accessors += ",{\"bufferView\":" + std::to_string(first + 1) + ",\"componentType\":5125,\"count\":" +
                 std::to_string(indices.size()) + ",\"type\":\"SCALAR\"}";
    viewCount += 2;
  };
  std::vector<Vertex> gridVertices, discVertices;
  std::vector<uint32_t> strip, fan;
  gridStrip(gridVertices, strip);
  discFan(discVertices, fan);
  addMesh(gridVertices, strip);
  addMesh(discVertices, fan);
  dir.write("mesh.bin", bin);
  const std::string json =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0,1]}],"
      "\"nodes\":[{\"mesh\":0,\"translation\":[-1.1,0,0]},{\"mesh\":1,\"translation\":[1.1,0,0]}],"
      "\"meshes\":[{\"name\":\"strip grid\",\"primitives\":[" + primitiveJson(0, 5) + "]},"
      "{\"name\":\"fan disc\",\"primitives\":[" + primitiveJson(4, 6) + "]}],"
      "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0},\"metallicFactor\":0,"
      "\"roughnessFactor\":0.6}}],"
      "\"textures\":[{\"source\":0}],\"images\":[{\"uri\":\"tiles.png\"}],"
      "\"buffers\":[{\"uri\":\"mesh.bin\",\"byteLength\":" + std::to_string(bin.size()) + "}],"
      "\"bufferViews\":[" + views + "],\"accessors\":[" + accessors + "]}";
  return dir.write("strips-and-fans.gltf", json);
}

TEST(StripsAndFans, ShadeDecoupledWithoutMisses) {
  TempDir dir;
  scene::Scene s = scene::loadGltf(writeStripsAndFans(dir));
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].triangleCount(), size_t(2 * kGrid * kGrid)) << "the strip's degenerate joins are dropped";
  EXPECT_EQ(s.meshes[1].triangleCount(), size_t(kRim));
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 2.5f,
                      .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.4f))});
  const scene::Camera camera = cameraAt({0.0f, 2.6f, 2.2f}, {0.0f, 0.0f, 0.0f});
  const BothPaths both = renderBothPaths(s, 128, 128, camera);
  EXPECT_EQ(both.decoupled.stats.objects, 2u) << "both meshes have a unique chart: both decoupled";
  expectFinite(both.forward, "strips/fans forward");
  expectClean(both.decoupled, "strips/fans decoupled");
  saveForInspection(both.decoupled, "strips-fans-decoupled");
  saveForInspection(both.forward, "strips-fans-forward");
  expectAgreement(both.decoupled, both.forward, {}, "strips and fans: decoupled vs forward");
}

}  // namespace
}  // namespace sg::test
