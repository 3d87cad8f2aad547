// Camera hard cases, validation on: the camera inside an object (a
// double-sided box seen from within: every wall wraps around the eye, the
// nearest ones with huge UV derivatives) and surfaces cut by the near plane.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 128;

TEST(Camera, InsideADoubleSidedObject) {
  scene::Scene s = makeLitSet();
  s.materials[1].doubleSided = true;  // the bricks crate (instance 1): seen from inside
  const glm::vec3 centre = glm::vec3(s.instances[1].world[3]);
  // Off centre, near a corner, looking at the far wall: walls at 0.2..1.3 units.
  const scene::Camera camera = cameraAt(centre + glm::vec3(0.4f, 0.3f, 0.45f), centre - glm::vec3(0.5f, 0.2f, 0.5f),
                                        0.01f, 50.0f, 1.2f);
  const BothPaths both = renderBothPaths(s, kSize, kSize, camera);
  expectFinite(both.forward, "inside forward");
  expectClean(both.decoupled, "inside decoupled");
  saveForInspection(both.decoupled, "inside-decoupled");
  saveForInspection(both.forward, "inside-forward");
  expectAgreement(both.decoupled, both.forward, {}, "inside an object: decoupled vs forward");
  EXPECT_GT(both.decoupled.stats.objects, 0u);
}

// The near plane at 0.5 cuts through the sphere and the ground: clipped
// triangles, shadels right at the clip edge.
TEST(Camera, NearPlaneCutsThroughObjects) {
  scene::Scene s = makeLitSet();
  const glm::vec3 sphere = glm::vec3(s.instances[2].world[3]);  // radius 1
  const scene::Camera camera = cameraAt(sphere + glm::vec3(0.0f, 0.1f, 1.3f), sphere - glm::vec3(0.3f, 0.4f, 0.0f),
                                        0.5f, 50.0f, 1.0f);
  const BothPaths both = renderBothPaths(s, kSize, kSize, camera);
  expectFinite(both.forward, "near plane forward");
  expectClean(both.decoupled, "near plane decoupled");
  saveForInspection(both.decoupled, "near-plane-decoupled");
  saveForInspection(both.forward, "near-plane-forward");
  expectAgreement(both.decoupled, both.forward, {}, "near-plane cut: decoupled vs forward");
}

}  // namespace
}  // namespace sg::test
