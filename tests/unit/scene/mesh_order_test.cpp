// Triangle and vertex order for the rasterizer (mesh_order.hpp): the same
// surface comes out, with better vertex reuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include <meshoptimizer.h>

#include <shadelgraph/scene/gltf_loader.hpp>
#include <shadelgraph/scene/mesh_order.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "scene_test_support.hpp"

namespace sg::scene {
namespace {

// A sphere with its triangles in random order, as CAD exporters leave them.
Primitive shuffledSphere() {
  Primitive p = makeSphere(1.0f, 48, 32);
  std::vector<std::array<uint32_t, 3>> triangles(p.triangleCount());
  std::copy_n(p.indices.begin(), p.indices.size(), &triangles[0][0]);
  std::shuffle(triangles.begin(), triangles.end(), std::mt19937(14));
  std::copy_n(&triangles[0][0], p.indices.size(), p.indices.begin());
  return p;
}

// Each triangle as its three corners' positions, first corner the smallest
// (a rotation keeps the winding), sorted: equal lists, equal surfaces.
std::vector<std::array<float, 9>> surface(const Primitive& p) {
  std::vector<std::array<float, 9>> out;
  for (size_t t = 0; t < p.indices.size(); t += 3) {
    std::array<std::array<float, 3>, 3> corners;
    for (size_t c = 0; c < 3; ++c) {
      const glm::vec3 v = p.positions[p.indices[t + c]];
      corners[c] = {v.x, v.y, v.z};
    }
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    std::array<float, 9>& flat = out.emplace_back();
    for (size_t c = 0; c < 3; ++c) std::copy(corners[c].begin(), corners[c].end(), flat.begin() + 3 * c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

float acmr(const Primitive& p) {
  return meshopt_analyzeVertexCache(p.indices.data(), p.indices.size(), p.vertexCount(), 16, 0, 0).acmr;
}

TEST(MeshOrder, VertexCacheKeepsTheTrianglesAndImprovesReuse) {
  const Primitive before = shuffledSphere();
  Primitive after = before;
  orderForRendering(after, {.vertexCache = true, .overdrawThreshold = 0.0f, .vertexFetch = false});
  EXPECT_EQ(after.positions, before.positions);  // no vertex moved
  EXPECT_EQ(surface(after), surface(before));
  EXPECT_NE(after.indices, before.indices);
  // Random order: ~2.6 vertices per triangle; optimized: below 0.8.
  EXPECT_GT(acmr(before), 2.0f);
  EXPECT_LT(acmr(after), 0.8f);
}

TEST(MeshOrder, AllStepsKeepTheSurfaceAndNumberVerticesByFirstUse) {
  Primitive before = shuffledSphere();
  before.colors.resize(before.vertexCount());
  for (size_t v = 0; v < before.vertexCount(); ++v) before.colors[v] = glm::vec4(before.positions[v], 1.0f);
  Primitive after = before;
  orderForRendering(after, {.vertexFetch = true});
  EXPECT_EQ(surface(after), surface(before));
  EXPECT_LT(acmr(after), 0.9f);  // overdraw ordering may give up up to 5% of the reuse
  // Every attribute array moved with its positions.
  ASSERT_EQ(after.vertexCount(), before.vertexCount());
  for (size_t v = 0; v < after.vertexCount(); ++v) {
    EXPECT_EQ(glm::vec3(after.colors[v]), after.positions[v]);
    EXPECT_TRUE(std::find(before.positions.begin(), before.positions.end(), after.positions[v]) != before.positions.end());
  }
  // Each index is a vertex seen before or the next new one.
  uint32_t next = 0;
  for (uint32_t index : after.indices) {
    ASSERT_LE(index, next);
    next += index == next;
  }
}

TEST(MeshOrder, UnusedVerticesStayAtTheEnd) {
  Primitive p = shuffledSphere();
  const size_t used = p.vertexCount();
  p.positions.push_back(glm::vec3(7.0f));
  p.normals.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
  p.uv0.push_back(glm::vec2(0.5f));
  orderForRendering(p, {.vertexFetch = true});
  ASSERT_EQ(p.vertexCount(), used + 1);
  EXPECT_EQ(p.positions.back(), glm::vec3(7.0f));
  EXPECT_EQ(p.uv0.back(), glm::vec2(0.5f));
}

TEST(MeshOrder, BlendedAndDeformedPrimitivesKeepTheirOrder) {
  const Primitive p = shuffledSphere();
  Material opaque, blended;
  blended.alphaMode = AlphaMode::Blend;
  EXPECT_TRUE(mayReorder(p, opaque));
  EXPECT_FALSE(mayReorder(p, blended));  // blended triangles composite in index order
  Primitive skinned = p;
  skinned.joints0.assign(p.vertexCount(), glm::uvec4(0));
  skinned.weights0.assign(p.vertexCount(), glm::vec4(1, 0, 0, 0));
  EXPECT_FALSE(mayReorder(skinned, opaque));
}

// The loader applies it, and the option turns it off.
TEST(MeshOrder, LoaderOrdersOnlyWhenAsked) {
  SG_REQUIRE_ASSETS();
  const std::filesystem::path file = test::samplePath("Duck");
  const Scene ordered = loadGltf(file, LoadOptions{.decodeImages = false});
  const Scene asFile = loadGltf(file, LoadOptions{.decodeImages = false,
                                                  .meshOrder = {.vertexCache = false, .overdrawThreshold = 0.0f, .vertexFetch = false}});
  const Primitive& a = ordered.meshes.at(0).primitives.at(0);
  const Primitive& b = asFile.meshes.at(0).primitives.at(0);
  EXPECT_EQ(surface(a), surface(b));
  EXPECT_NE(a.indices, b.indices);
  EXPECT_LE(acmr(a), acmr(b));
}

}  // namespace
}  // namespace sg::scene
