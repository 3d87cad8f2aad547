// Shadow maps' hard cases, validation on, both paths, for each kind of map
// (a spot's, a point light's cube, a directional light's cascades; docs/stability.md):
// - acne: a plane lit at grazing angles (5°, 1°) is as smooth as without
//   shadows (neighbouring pixels of the HDR image differ by under 2% of the
//   mean) and keeps its light (at least 97% of it);
// - contact (peter-panning): a sphere resting on the plane casts the shadow
//   the geometry gives, pixel by pixel (ShadowContact below says how).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <shadelgraph/graph/plan_dump.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;

float luminance(const glm::vec4& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

const char* typeName(scene::LightType type) {
  return type == scene::LightType::Spot ? "Spot" : type == scene::LightType::Point ? "Point" : "Sun";
}

// A grey diffuse plane, a sphere of radius `radius` resting on it at
// (sphereX, 0), and one light arriving at `elevationDegrees` above the plane
// along +z at `target`: a spot aimed at it or a point light, `distance` away,
// or a directional light.
scene::Scene plateWithSphere(scene::LightType type, float elevationDegrees, float distance, glm::vec3 target,
                             float radius, bool shadows, float sphereX = 0.0f) {
  scene::Scene s;
  const int grey = addMaterial(s, {.name = "plate", .baseColorFactor = {0.5f, 0.5f, 0.5f, 1.0f},
                                   .metallicFactor = 0.0f, .roughnessFactor = 1.0f});
  const int ball = addMaterial(s, {.name = "ball", .baseColorFactor = {0.7f, 0.3f, 0.2f, 1.0f},
                                   .metallicFactor = 0.0f, .roughnessFactor = 0.6f});
  // Finely split: an untextured mesh's decoupled level 0 follows its triangle count
  // (framework/shadel/level0_resolution.hpp), so the plane gets about 2 cm shadels.
  placeMesh(s, scene::makePlane(12.0f, 12.0f, 128), grey, glm::mat4(1.0f));
  placeMesh(s, scene::makeSphere(radius, 64, 32), ball, glm::translate(glm::mat4(1.0f), {sphereX, radius, 0.0f}));
  const float e = glm::radians(elevationDegrees);
  const glm::vec3 dir{0.0f, -std::sin(e), std::cos(e)};
  s.lights.push_back({.name = typeName(type), .type = type,
                      .intensity = type == scene::LightType::Directional ? 1e3f : 4e5f, .innerConeAngle = 0.25f,
                      .outerConeAngle = 0.3f, .position = target - dir * distance, .direction = dir,
                      .shadows = shadows});
  return s;
}

bool holdsShadowPass(StabilitySession& session, const scene::Camera& camera) {
  const auto plan = nlohmann::json::parse(graph::toJson(session.plan(64, 64, camera)));
  for (const auto& p : plan["passes"])
    if (p["name"] == "shadows" && !p["culled"].get<bool>()) return true;
  return false;
}

StabilityFrame renderChecked(const scene::Scene& s, scene::ShadingMode mode, const scene::Camera& camera,
                             bool expectShadowPass, const std::string& what, uint32_t size = kSize) {
  StabilitySession session(s, mode);
  EXPECT_EQ(holdsShadowPass(session, camera), expectShadowPass) << what;
  StabilityFrame f = session.render(size, camera);
  if (mode == scene::ShadingMode::Decoupled) expectClean(f, what);
  else expectFinite(f, what);
  return f;
}

struct Smoothness {
  double mean = 0.0;         // HDR luminance over the window
  double neighbour = 0.0;    // mean |difference| of right and lower neighbours, over the mean
};

// Over the window [x0, x1) x [y0, y1) of the HDR image.
Smoothness smoothness(const StabilityFrame& f, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
  const uint32_t w = f.ldr.width;
  double sum = 0.0, diff = 0.0;
  size_t n = 0, pairs = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) {
      const double l = luminance(f.hdr[size_t(y) * w + x]);
      sum += l;
      ++n;
      if (x + 1 < x1) diff += std::abs(l - double(luminance(f.hdr[size_t(y) * w + x + 1]))), ++pairs;
      if (y + 1 < y1) diff += std::abs(l - double(luminance(f.hdr[size_t(y + 1) * w + x]))), ++pairs;
    }
  Smoothness s;
  s.mean = sum / double(n);
  s.neighbour = diff / double(pairs) / s.mean;
  return s;
}

struct Grazing {
  scene::LightType type;
  const char* angle;
  float degrees;
};

class ShadowAcne : public ::testing::TestWithParam<Grazing> {};

TEST_P(ShadowAcne, AGrazingLitPlaneStaysSmoothAndLit) {
  const Grazing g = GetParam();
  const std::string name = std::string(typeName(g.type)) + g.angle;
  // The plane lit at `degrees`; the view holds only plane (the sphere and its shadow are 3 units aside).
  const glm::vec3 target{0.0f, 0.0f, 4.0f};
  const scene::Camera camera = cameraAt({0.0f, 3.0f, 6.5f}, target, 0.1f, 100.0f, 0.6f);
  for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) {
    const std::string what = name + (mode == scene::ShadingMode::Forward ? " forward" : " decoupled");
    const StabilityFrame shadowed =
        renderChecked(plateWithSphere(g.type, g.degrees, 20.0f, target, 0.5f, true, 3.0f), mode, camera, true, what);
    const StabilityFrame unshadowed = renderChecked(plateWithSphere(g.type, g.degrees, 20.0f, target, 0.5f, false, 3.0f),
                                                    mode, camera, false, what + " (off)");
    saveForInspection(shadowed, "shadow_acne_" + name + (mode == scene::ShadingMode::Forward ? "_fwd" : "_dec"));
    const Smoothness on = smoothness(shadowed, 8, 8, kSize - 8, kSize - 8);
    const Smoothness off = smoothness(unshadowed, 8, 8, kSize - 8, kSize - 8);
    std::printf("%-22s mean %.4f (without shadows %.4f, kept %.4f), neighbour |d| %.4f of the mean (without %.4f)\n",
                what.c_str(), on.mean, off.mean, on.mean / off.mean, on.neighbour, off.neighbour);
    EXPECT_LT(on.neighbour, 0.02) << what << ": an acne pattern";
    EXPECT_GT(on.mean / off.mean, 0.97) << what << ": the lit plane shadows itself";
  }
}

std::vector<Grazing> grazingCases() {
  std::vector<Grazing> out;
  for (auto type : {scene::LightType::Spot, scene::LightType::Directional, scene::LightType::Point})
    for (const auto& [angle, degrees] : {std::pair{"Grazing5Degrees", 5.0f}, std::pair{"Grazing1Degree", 1.0f}})
      out.push_back({type, angle, degrees});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Angles, ShadowAcne, ::testing::ValuesIn(grazingCases()), [](const auto& param_info) {
  return std::string(typeName(param_info.param.type)) + param_info.param.angle;
});

// The ground point a pixel centre sees, when the ray meets the ground before the sphere.
std::optional<glm::vec3> groundSeenBy(const scene::Camera& camera, uint32_t size, uint32_t x, uint32_t y,
                                      glm::vec3 centre, float radius) {
  const glm::mat4 inverse = glm::inverse(camera.projectionMatrix(1.0f) * camera.view());
  const glm::vec2 ndc{(float(x) + 0.5f) / float(size) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(size) * 2.0f};
  const glm::vec4 far = inverse * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 eye = camera.position(), dir = glm::normalize(glm::vec3(far) / far.w - eye);
  if (dir.y >= 0.0f) return std::nullopt;
  const float tGround = -eye.y / dir.y;
  const glm::vec3 oc = eye - centre;
  const float b = glm::dot(oc, dir), disc = b * b - (glm::dot(oc, oc) - radius * radius);
  if (disc > 0.0f && -b - std::sqrt(disc) < tGround) return std::nullopt;  // the sphere is in front
  return eye + dir * tGround;
}

// How far from the sphere's centre the segment from a ground point to the light passes, in radii.
float missDistance(glm::vec3 ground, glm::vec3 light, glm::vec3 centre, float radius) {
  const glm::vec3 d = light - ground;
  const float t = std::clamp(glm::dot(centre - ground, d) / glm::dot(d, d), 0.0f, 1.0f);
  return glm::length(ground + d * t - centre) / radius;
}

// Contact: the rendered shadow matches the analytic shadow of the sphere on
// the ground pixel by pixel, so it reaches the contact and does not shrink
// (peter-panning) or leak. Each pixel is compared with the same pixel of the
// render with `shadows: false` (which cancels the spot's falloff): every
// ground pixel whose segment to the light passes within 0.8 r of the centre
// keeps at most 15% of its light more than the umbra does (the sky's share), every one passing beyond 1.2 r over 90%; the
// band between is the penumbra of the filter and the pixel footprint.
class ShadowContact : public ::testing::TestWithParam<scene::LightType> {};

TEST_P(ShadowContact, ASphereOnAPlaneCastsItsAnalyticShadow) {
  constexpr float kRadius = 0.5f, kElevation = 35.0f, kDistance = 6.0f;
  constexpr uint32_t kView = 128;
  const scene::LightType type = GetParam();
  const glm::vec3 centre{0.0f, kRadius, 0.0f};
  // Light along +z, so the shadow lies at z > 0; the camera looks across it from the side.
  const scene::Camera camera = cameraAt({3.0f, 1.5f, 0.3f}, {0.0f, 0.0f, 0.3f}, 0.1f, 100.0f, 0.8f);
  const scene::Light sceneLight = plateWithSphere(type, kElevation, kDistance, {}, kRadius, true).lights[0];
  // Where the light comes from, seen from a ground point (a directional light: far along its direction).
  const auto lightFrom = [&](glm::vec3 ground) {
    return type == scene::LightType::Directional ? ground - sceneLight.direction * 1e4f : sceneLight.position;
  };
  for (auto mode : {scene::ShadingMode::Forward, scene::ShadingMode::Decoupled}) {
    const std::string what = std::string(typeName(type)) + (mode == scene::ShadingMode::Forward ? " contact forward" : " contact decoupled");
    const StabilityFrame f = renderChecked(plateWithSphere(type, kElevation, kDistance, {}, kRadius, true), mode,
                                           camera, true, what, kView);
    const StabilityFrame off = renderChecked(plateWithSphere(type, kElevation, kDistance, {}, kRadius, false), mode,
                                             camera, false, what + " (off)", kView);
    saveForInspection(f, std::string("shadow_contact_") + typeName(type) +
                             (mode == scene::ShadingMode::Forward ? "_fwd" : "_dec"));
    size_t dark = 0, darkNearContact = 0, lit = 0, wrongDark = 0, wrongLit = 0;
    double worstDark = 0.0, worstLit = 1e30, umbra = 1e30;
    std::vector<double> darkRatios;
    for (uint32_t y = 0; y < kView; ++y)
      for (uint32_t x = 0; x < kView; ++x) {
        const auto g = groundSeenBy(camera, kView, x, y, centre, kRadius);
        if (!g) continue;
        const size_t i = size_t(y) * kView + x;
        const double ratio = double(luminance(f.hdr[i])) / std::max(double(luminance(off.hdr[i])), 1e-6);
        const float miss = missDistance(*g, lightFrom(*g), centre, kRadius);
        if (miss < 0.8f) {
          ++dark;
          if (glm::length(*g) < kRadius) ++darkNearContact;
          worstDark = std::max(worstDark, ratio);
          umbra = std::min(umbra, ratio);
          darkRatios.push_back(ratio);
        } else if (miss > 1.2f) {
          ++lit;
          worstLit = std::min(worstLit, ratio);
          if (ratio <= 0.9) ++wrongLit;
        }
      }
    // What the shadow keeps is the sky's light (cd/m^2, a fifth of a sunlit ground's under a
    // physical sky; ~0 under a lamp): a shadowed pixel is wrong 0.15 above the umbra.
    for (const double r : darkRatios) wrongDark += r >= umbra + 0.15;
    EXPECT_LT(umbra, 0.3) << what << ": the umbra keeps more than the sky could give";
    std::printf("%s: %zu shadowed ground pixels (%zu within 1 r of the contact), light kept %.3f..%.3f; %zu lit, "
                "least kept %.3f; wrong: %zu dark, %zu lit\n",
                what.c_str(), dark, darkNearContact, umbra, worstDark, lit, worstLit, wrongDark, wrongLit);
    EXPECT_GE(darkNearContact, 20u) << what << ": the contact is not in view";
    EXPECT_GE(lit, 1000u) << what;
    EXPECT_EQ(wrongDark, 0u) << what << ": shadowed ground lit (a detached or leaking shadow)";
    EXPECT_EQ(wrongLit, 0u) << what << ": lit ground shadowed (acne or a shadow too large)";
  }
}

INSTANTIATE_TEST_SUITE_P(Lights, ShadowContact,
                         ::testing::Values(scene::LightType::Spot, scene::LightType::Directional, scene::LightType::Point),
                         [](const auto& param_info) { return std::string(typeName(param_info.param)); });

}  // namespace
}  // namespace sg::test
