// The object-pick pass (a viewer click): the nearest object under the pixel,
// and an alpha-mask object only where its alpha test keeps it, so a click
// through a cut-out picks what is behind it. Validation on.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 64;

// A grey box, and in front of it a thin alpha-mask card whose base colour
// alpha is `cardAlpha` (cutoff 0.5): below it the test cuts the whole card away.
scene::Scene cardBeforeBox(float cardAlpha) {
  scene::Scene s;
  s.materials.push_back({.name = "grey", .baseColorFactor = {0.6f, 0.6f, 0.6f, 1.0f}, .metallicFactor = 0.0f,
                         .roughnessFactor = 0.5f});
  s.materials.push_back({.name = "card", .baseColorFactor = {0.2f, 0.8f, 0.2f, cardAlpha}, .metallicFactor = 0.0f,
                         .roughnessFactor = 0.5f, .alphaMode = scene::AlphaMode::Mask, .alphaCutoff = 0.5f,
                         .doubleSided = true});
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 3.0f,
                      .direction = glm::normalize(glm::vec3(-1.0f, -2.0f, -1.5f))});
  const auto add = [&](std::string name, scene::Primitive p, int material, glm::vec3 at) {
    p.material = material;
    scene::Mesh mesh{.name = name, .bounds = p.bounds};
    mesh.primitives.push_back(std::move(p));
    s.meshes.push_back(std::move(mesh));
    s.instances.push_back({int(s.meshes.size() - 1), glm::translate(glm::mat4(1.0f), at), name});
  };
  add("box", scene::makeBox(glm::vec3(1.0f)), 0, {0.0f, 0.0f, -1.0f});
  add("card", scene::makeBox(glm::vec3(2.0f, 2.0f, 0.05f)), 1, {0.0f, 0.0f, 1.0f});
  return s;
}

std::optional<uint32_t> pickCentre(Session& session) {
  const auto result = session.renderer().render({.width = kSize, .height = kSize,
                                                 .cameraOverride = lookAtCamera({0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}),
                                                 .pick = glm::uvec2(kSize / 2, kSize / 2)});
  EXPECT_TRUE(result.pickAnswered);
  return result.picked;
}

class ObjectPick : public ::testing::TestWithParam<scene::ShadingMode> {};

TEST_P(ObjectPick, AClickThroughACutOutPicksWhatIsBehind) {
  Session kept(cardBeforeBox(0.9f), GetParam()), cut(cardBeforeBox(0.2f), GetParam());
  EXPECT_EQ(pickCentre(kept), std::optional<uint32_t>(instanceNamed(kept.scene(), "card")));
  EXPECT_EQ(pickCentre(cut), std::optional<uint32_t>(instanceNamed(cut.scene(), "box")))
      << "the card's alpha test cuts it away at the pixel";
}

INSTANTIATE_TEST_SUITE_P(Modes, ObjectPick, ::testing::Values(scene::ShadingMode::Forward, scene::ShadingMode::Decoupled),
                         [](const auto& mode) {
                           return mode.param == scene::ShadingMode::Forward ? std::string("forward")
                                                                            : std::string("decoupled");
                         });

}  // namespace
}  // namespace sg::test
