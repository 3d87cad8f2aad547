// The closed-surface test behind culling double-sided back faces (closed_surface.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <shadelgraph/scene/closed_surface.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

namespace sg::scene {
namespace {

// A unit cube with one vertex per corner, counter-clockwise seen from outside:
// 12 triangles, two per face (the face's four corners in order).
struct Cube {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;

  explicit Cube(glm::vec3 offset = glm::vec3(0.0f)) {
    for (uint32_t i = 0; i < 8; ++i)
      positions.push_back(offset + glm::vec3(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1)));
    const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) indices.insert(indices.end(), {f[0], f[1], f[2], f[0], f[2], f[3]});
  }
  void invert() {
    for (size_t t = 0; t < indices.size(); t += 3) std::swap(indices[t + 1], indices[t + 2]);
  }
  void append(const Cube& other) {
    const auto base = uint32_t(positions.size());
    positions.insert(positions.end(), other.positions.begin(), other.positions.end());
    for (uint32_t i : other.indices) indices.push_back(base + i);
  }
  bool closed() const { return isClosedSurface(positions, indices); }
};

TEST(ClosedSurface, CubeIsClosed) { EXPECT_TRUE(Cube().closed()); }

TEST(ClosedSurface, CubeWithoutAFaceIsOpen) {
  Cube cube;
  cube.indices.resize(cube.indices.size() - 6);
  EXPECT_FALSE(cube.closed());
  cube = Cube();
  cube.indices.resize(cube.indices.size() - 3);  // half a face: a hole of one triangle
  EXPECT_FALSE(cube.closed());
}

TEST(ClosedSurface, InvertedWindingIsNotOutward) {
  Cube cube;
  cube.invert();
  EXPECT_FALSE(cube.closed()) << "closed, but wound inward: the back faces are the ones seen";
}

TEST(ClosedSurface, OneFlippedTriangleIsInconsistent) {
  Cube cube;
  std::swap(cube.indices[1], cube.indices[2]);
  EXPECT_FALSE(cube.closed());
}

TEST(ClosedSurface, EveryPartMustFaceOutward) {
  Cube two;
  two.append(Cube(glm::vec3(3.0f, 0.0f, 0.0f)));
  EXPECT_TRUE(two.closed());
  // A small inverted cube beside a large outward one: the total volume is positive, but its back faces show.
  Cube mixed;
  for (glm::vec3& p : mixed.positions) p *= 4.0f;
  Cube inverted(glm::vec3(10.0f, 0.0f, 0.0f));
  inverted.invert();
  mixed.append(inverted);
  EXPECT_FALSE(mixed.closed());
}

TEST(ClosedSurface, EdgeSharedByMoreThanTwoTrianglesIsRejected) {
  Cube cube;
  cube.indices.insert(cube.indices.end(), cube.indices.begin(), cube.indices.begin() + 3);  // a duplicated triangle
  EXPECT_FALSE(cube.closed());
}

TEST(ClosedSurface, SplitSeamsStillClose) {
  // makeBox: 24 vertices (normals and UVs split at every edge), positions shared bitwise.
  const Primitive box = makeBox(glm::vec3(1.0f, 2.0f, 3.0f));
  ASSERT_EQ(box.positions.size(), 24u);
  EXPECT_TRUE(isClosedSurface(box.positions, box.indices));
  // The same with every triangle's corners given vertices of their own.
  std::vector<glm::vec3> soup;
  std::vector<uint32_t> indices;
  for (uint32_t i : box.indices) {
    indices.push_back(uint32_t(soup.size()));
    soup.push_back(box.positions[i]);
  }
  EXPECT_TRUE(isClosedSurface(soup, indices));
  // A seam whose positions differ in the last bit does not weld: an open surface (a crack).
  soup[indices[0]].x = std::nextafter(soup[indices[0]].x, 10.0f);
  EXPECT_FALSE(isClosedSurface(soup, indices));
}

TEST(ClosedSurface, DegenerateTrianglesAreIgnored) {
  Cube cube;
  cube.indices.insert(cube.indices.end(), {0, 0, 1, 2, 2, 2});  // no area: no edges of the surface
  EXPECT_TRUE(cube.closed());
}

TEST(ClosedSurface, PlaneAndBadInput) {
  const Primitive plane = makePlane(1.0f, 1.0f, 2);
  EXPECT_FALSE(isClosedSurface(plane.positions, plane.indices));
  Cube cube;
  EXPECT_FALSE(isClosedSurface(cube.positions, {}));
  cube.indices.back() = 8;  // out of range
  EXPECT_FALSE(cube.closed());
}

}  // namespace
}  // namespace sg::scene
