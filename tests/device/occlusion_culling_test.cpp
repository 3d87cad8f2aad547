// Occlusion culling never hides what is visible: along a camera path that
// starts with spheres hidden behind the courtyard's back wall, rises until
// they show over it, jumps behind the wall and comes back, every frame with
// culling is the same image as without, forward and decoupled, validation on.
// The path must also cull something (else it would prove nothing). The same
// with forward-opaque drawing the depth itself (no z-prepass).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr int kHiddenSpheres = 6;

// The default courtyard with a row of spheres behind its back wall (z = -8, 4 high).
scene::Scene courtyardWithHiddenSpheres() {
  return courtyardWithSphereRow("hidden sphere", kHiddenSpheres, {-5.0f, 1.0f, -10.5f}, scene::ShadingMode::Auto);
}

// The path: hidden, rising until the spheres show over the wall, a jump
// behind the wall (nothing drawn last frame is in front of them), and back.
std::vector<scene::Camera> path() {
  std::vector<scene::Camera> cameras;
  for (float y : {3.2f, 3.2f, 5.0f, 7.0f, 9.0f}) cameras.push_back(lookAtCamera({1.5f, y, 8.5f}, {0.0f, 1.0f, -4.0f}));
  cameras.push_back(lookAtCamera({0.0f, 2.0f, -16.0f}, {0.0f, 1.0f, -10.0f}));
  cameras.push_back(lookAtCamera({1.5f, 3.2f, 8.5f}, {0.0f, 1.0f, -4.0f}));
  cameras.push_back(lookAtCamera({-6.5f, 1.5f, 6.0f}, {-2.0f, 1.0f, -9.0f}));
  return cameras;
}

// Along the path, culled and unculled frames match and the hidden spheres are
// culled where the wall hides them; `zPrepass` Off: forward-opaque draws the
// depth and culls in its own two halves.
void expectSameImagesAlongThePath(scene::ShadingMode mode, render::ZPrepass zPrepass) {
  const scene::Scene scene = courtyardWithHiddenSpheres();
  Session culled(scene, mode), unculled(scene, mode);
  const size_t firstHidden = scene.instances.size() - kHiddenSpheres;
  int framesWithCulledSpheres = 0, framesWithVisibleSpheres = 0;
  const auto cameras = path();
  for (size_t f = 0; f < cameras.size(); ++f) {
    const auto a =
        culled.renderer().render({.width = 160, .height = 120, .cameraOverride = cameras[f], .zPrepass = zPrepass}).image;
    const auto b = unculled.renderer()
                       .render({.width = 160, .height = 120, .cameraOverride = cameras[f], .occlusionCulling = false,
                                .zPrepass = zPrepass})
                       .image;
    const auto diff = image::compareRgba8(a.rgba8, b.rgba8);
    EXPECT_EQ(diff.maxAbs, 0) << "frame " << f << ": culled and unculled images differ (mean |d| " << diff.meanAbs
                              << ", " << diff.fractionAbove8 * 100 << "% of pixels by more than 8/255)";
    const auto visible = culled.renderer().culling().lastVisible();
    const auto& draws = culled.renderer().gpuScene().draws();
    int hiddenCulled = 0, hiddenVisible = 0;
    for (size_t d = 0; d < draws.size(); ++d)
      if (draws[d].instance >= firstHidden) (visible[d] ? hiddenVisible : hiddenCulled)++;
    if (hiddenCulled == kHiddenSpheres) ++framesWithCulledSpheres;
    if (hiddenVisible > 0) ++framesWithVisibleSpheres;
  }
  // The start of the path hides every sphere behind the wall, and culling finds that.
  EXPECT_GE(framesWithCulledSpheres, 2);
  // Higher up and behind the wall they are seen, and drawn.
  EXPECT_GE(framesWithVisibleSpheres, 2);
  if (mode == scene::ShadingMode::Decoupled) {
    EXPECT_EQ(culled.stats().counters.compositeMisses, 0u);
  }
}

class OcclusionCulling : public ::testing::TestWithParam<scene::ShadingMode> {};

TEST_P(OcclusionCulling, SameImagesAsWithoutAlongACameraPath) {
  expectSameImagesAlongThePath(GetParam(), render::ZPrepass::On);
}

// Without the depth pre-pass (a forward frame where it does not pay).
TEST(OcclusionCullingWithoutZPrepass, SameImagesAsWithoutAlongACameraPath) {
  expectSameImagesAlongThePath(scene::ShadingMode::Forward, render::ZPrepass::Off);
}

// A hidden sphere moved out in front of the wall (Renderer::setObjectTransform)
// is tested at its new place: culled by its old bounds it would vanish.
TEST_P(OcclusionCulling, AMovedObjectIsTestedWhereItIsNow) {
  const scene::Scene scene = courtyardWithHiddenSpheres();
  Session culled(scene, GetParam()), unculled(scene, GetParam());
  const uint32_t moved = uint32_t(scene.instances.size() - 1);
  const scene::Camera view = path().front();
  const auto hidden = culled.renderer().render({.width = 160, .height = 120, .cameraOverride = view}).image;
  const glm::mat4 inFront = glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 2.0f});
  culled.renderer().setObjectTransform(moved, inFront);
  unculled.renderer().setObjectTransform(moved, inFront);
  const auto a = culled.renderer().render({.width = 160, .height = 120, .cameraOverride = view}).image;
  const auto b =
      unculled.renderer().render({.width = 160, .height = 120, .cameraOverride = view, .occlusionCulling = false}).image;
  EXPECT_GT(image::compareRgba8(hidden.rgba8, b.rgba8).maxAbs, 0) << "the moved sphere must be in view";
  EXPECT_EQ(image::compareRgba8(a.rgba8, b.rgba8).maxAbs, 0) << "the moved sphere was culled by its old bounds";
}

INSTANTIATE_TEST_SUITE_P(Paths, OcclusionCulling,
                         ::testing::Values(scene::ShadingMode::Forward, scene::ShadingMode::Decoupled),
                         pathName);

}  // namespace
}  // namespace sg::test
