// Back faces of closed surfaces are culled while the camera is outside them,
// even for double-sided materials (scene/closed_surface.hpp,
// render/scene_view.hpp): the image is the same as without culling, forward and
// decoupled (z-prepass, forward-opaque, shadel-mark and composite all draw
// them), validation on; and the culling does happen: an open box that claims
// to be closed loses its inside seen through the hole.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/closed_surface.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

// Positions snapped to 1/1024: the procedural sphere's seam vertices (sin 2pi
// is not 0 in floats) become bitwise equal, so the sphere is closed.
scene::Primitive snapped(scene::Primitive p) {
  // (+ 0: rounding leaves -0, which does not weld with +0.)
  for (glm::vec3& position : p.positions) position = glm::round(position * 1024.0f) / 1024.0f + 0.0f;
  p.bounds = {};
  for (const glm::vec3& position : p.positions) p.bounds.extend(position);
  p.closedSurface = scene::isClosedSurface(p.positions, p.indices);
  return p;
}

// A box missing its +Z face (two triangles), marked closed all the same.
scene::Primitive openBoxClaimingClosed() {
  scene::Primitive box = scene::makeBox(glm::vec3(1.6f));
  for (size_t t = 0; t < box.indices.size(); t += 3) {
    const glm::vec3 n = glm::cross(box.positions[box.indices[t + 1]] - box.positions[box.indices[t]],
                                   box.positions[box.indices[t + 2]] - box.positions[box.indices[t]]);
    if (n.z > 0.5f) {
      box.indices.erase(box.indices.begin() + std::ptrdiff_t(t), box.indices.begin() + std::ptrdiff_t(t) + 3);
      t -= 3;
    }
  }
  box.closedSurface = true;
  return box;
}

// Two double-sided objects: a sphere and a box (closed), or the open box; `closed` false clears the flags.
scene::Scene scene(bool closed, bool openBox = false) {
  scene::Scene s;
  s.materials.push_back({.name = "double-sided orange", .baseColorFactor = {0.9f, 0.4f, 0.1f, 1.0f},
                         .metallicFactor = 0.0f, .roughnessFactor = 0.5f, .doubleSided = true});
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
                      .direction = glm::normalize(glm::vec3(-1.0f, -2.0f, -1.5f))});
  auto add = [&](std::string name, scene::Primitive p, glm::vec3 at) {
    if (!closed) p.closedSurface = false;
    scene::Mesh mesh{.name = name, .bounds = p.bounds};
    mesh.primitives.push_back(std::move(p));
    s.meshes.push_back(std::move(mesh));
    s.instances.push_back({int(s.meshes.size() - 1), glm::translate(glm::mat4(1.0f), at), name});
  };
  if (openBox) {
    add("open box", openBoxClaimingClosed(), {0.0f, 0.0f, 0.0f});
  } else {
    add("sphere", snapped(scene::makeSphere(1.0f, 32, 16)), {-1.2f, 0.0f, 0.0f});
    add("box", snapped(scene::makeBox(glm::vec3(1.4f))), {1.3f, 0.2f, -0.5f});
  }
  return s;
}

class ClosedSurfaceCulling : public ::testing::TestWithParam<scene::ShadingMode> {};

TEST_P(ClosedSurfaceCulling, SameImageAsWithoutFromOutside) {
  const scene::Scene withFlags = scene(true);
  ASSERT_TRUE(withFlags.meshes[0].primitives[0].closedSurface) << "the snapped sphere must be closed";
  ASSERT_TRUE(withFlags.meshes[1].primitives[0].closedSurface);
  Session culled(withFlags, GetParam()), unculled(scene(false), GetParam());
  for (const auto& view : {lookAtCamera({0.5f, 1.5f, 5.0f}, {0.0f, 0.0f, 0.0f}), lookAtCamera({-4.0f, -1.0f, 1.0f}, {0.0f, 0.0f, 0.0f}),
                           lookAtCamera({-1.2f, 0.0f, 2.0f}, {-1.2f, 0.0f, 0.0f})}) {  // the last near the sphere's bounds
    const auto a = culled.render(160, view), b = unculled.render(160, view);
    const auto diff = image::compareRgba8(a.rgba8, b.rgba8);
    EXPECT_EQ(diff.maxAbs, 0) << "mean |d| " << diff.meanAbs << ", " << diff.fractionAbove8 * 100
                              << "% of pixels by more than 8/255";
  }
  if (GetParam() == scene::ShadingMode::Decoupled) {
    EXPECT_EQ(culled.stats().counters.compositeMisses, 0u);
  }
}

TEST_P(ClosedSurfaceCulling, InsideTheSurfaceItsInsideIsDrawn) {
  // The camera in the sphere: no culling there, so it still sees the sphere's inside.
  Session culled(scene(true), GetParam()), unculled(scene(false), GetParam());
  const auto inside = lookAtCamera({-1.2f, 0.0f, 0.3f}, {-1.2f, 0.0f, -1.0f});
  const auto a = culled.render(96, inside), b = unculled.render(96, inside);
  EXPECT_EQ(image::compareRgba8(a.rgba8, b.rgba8).maxAbs, 0);
}

TEST_P(ClosedSurfaceCulling, BackFacesAreCulledFromOutside) {
  // Through the open box's missing face its inside shows, unless back faces are culled.
  Session culled(scene(true, true), GetParam()), unculled(scene(false, true), GetParam());
  const auto front = lookAtCamera({0.3f, 0.4f, 4.0f}, {0.0f, 0.0f, 0.0f});
  const auto a = culled.render(96, front), b = unculled.render(96, front);
  const auto diff = image::compareRgba8(a.rgba8, b.rgba8);
  EXPECT_GT(diff.fractionAbove8, 0.1) << "the inside of the box (back faces) must be culled in every pass";
  // Seen from inside the box, nothing is culled: the same image.
  const auto inside = lookAtCamera({0.0f, 0.0f, 0.2f}, {0.0f, 0.0f, -1.0f});
  EXPECT_EQ(image::compareRgba8(culled.render(96, inside).rgba8, unculled.render(96, inside).rgba8).maxAbs, 0);
}

INSTANTIATE_TEST_SUITE_P(Paths, ClosedSurfaceCulling,
                         ::testing::Values(scene::ShadingMode::Forward, scene::ShadingMode::Decoupled),
                         pathName);

}  // namespace
}  // namespace sg::test
