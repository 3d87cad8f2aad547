// fp16 overflow, validation on: an emissive of 1e5 (above half precision's
// 65,504) in the RGBA16F shade storage and HDR target must not become Inf,
// nor turn its filtered neighbours into NaN (Inf x 0 weight), nor make the
// exposure non-finite.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 128;

scene::Scene withGlowingSphere(float emissive) {
  scene::Scene s = makeLitSet();
  scene::Material glow{.name = "glow", .metallicFactor = 0.0f, .roughnessFactor = 0.5f,
                       .emissiveFactor = glm::vec3(emissive)};
  placeMesh(s, scene::makeSphere(0.5f, 32, 16), addMaterial(s, glow), glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, 1.5f}));
  return s;
}

TEST(Fp16Overflow, EmissiveAboveHalfMaxStaysFinite) {
  const BothPaths both = renderBothPaths(withGlowingSphere(1e5f), kSize, kSize);
  for (const auto* frame : {&both.forward, &both.decoupled}) {
    const std::string what = frame == &both.forward ? "emissive 1e5 forward" : "emissive 1e5 decoupled";
    expectFinite(*frame, what);
    const HdrSummary s = summarize(frame->hdr);
    std::printf("%s: HDR max %.0f, exposure %.3f\n", what.c_str(), double(s.maxValue), s.exposure);
    EXPECT_GE(s.maxValue, 60000.0f) << what << ": the glow is clamped to the format's range, not lost";
    // The glowing sphere saturates, the rest is still drawn (the exposure is finite and not zero).
    EXPECT_GT(meanLevel(frame->ldr), 1.0) << what;
  }
  expectClean(both.decoupled, "emissive 1e5 decoupled");
  expectAgreement(both.decoupled, both.forward, {}, "emissive 1e5: decoupled vs forward");
}

}  // namespace
}  // namespace sg::test
