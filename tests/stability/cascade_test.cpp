// A directional light's cascades with a moving camera (docs/stability.md):
// the camera walks forward over a field of posts in a low sun, exactly one
// post spacing in 24 steps, forward path, validation on. Asserted, frame by
// frame: the cascades' extents (their ends in view depth) do not change, and
// each cascade's texel grid stays put in the world (a fixed world point falls
// on the same fraction of a texel, and a unit step across the ground spans
// the same texels: snapped, constant-size cascades, so shadow edges do not
// crawl). Measured and printed, not asserted: the frame-to-frame change of
// ground pixels at each cascade boundary and beside it; it is dominated by
// the shadows' own motion across pixels (a control without blending and
// without snapping gives the same figures, mean or rms), so it cannot tell a
// stable transition from an unstable one: cascade_flicker_test.cpp measures
// the transition world-stably.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include <shadelgraph/render/shadow_views.hpp>
#include <shadelgraph/scene/bounds.hpp>
#include <shadelgraph/scene/procedural_meshes.hpp>

#include "stability_checks.hpp"
#include "stability_scenes.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kWidth = 192, kHeight = 128;
// The camera walks exactly one post spacing, so each band sees every phase of the field.
constexpr int kFrames = 25;

float luminance(const glm::vec4& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

scene::Scene postField() {
  scene::Scene s;
  const int ground = addMaterial(s, {.name = "ground", .baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f),
                                     .metallicFactor = 0.0f, .roughnessFactor = 1.0f});
  const int wood = addMaterial(s, {.name = "post", .baseColorFactor = {0.6f, 0.45f, 0.3f, 1.0f},
                                   .metallicFactor = 0.0f, .roughnessFactor = 0.8f});
  placeMesh(s, scene::makePlane(80.0f, 80.0f, 8), ground, glm::mat4(1.0f));
  for (int z = 1; z <= 16; ++z)
    for (int x = -5; x <= 5; ++x)
      placeMesh(s, scene::makeCylinder(0.06f, 1.0f, 8), wood,
                glm::translate(glm::mat4(1.0f), {float(x), 0.0f, -float(z)}));
  s.lights.push_back({.name = "low sun", .type = scene::LightType::Directional, .intensity = 1e3f,
                      .direction = glm::normalize(glm::vec3(-0.7f, -0.45f, -0.35f))});
  return s;
}

scene::Camera cameraOfFrame(int t) {
  const glm::vec3 eye{0.0f, 1.6f, -float(t) / float(kFrames - 1)};
  return cameraAt(eye, eye + glm::vec3(0.0f, -1.6f, -8.0f), 0.1f, 100.0f, 0.8f);
}

// The view depth of the ground point a pixel centre sees (none: it sees the sky).
std::optional<float> groundDepth(const scene::Camera& camera, uint32_t x, uint32_t y) {
  const float aspect = float(kWidth) / float(kHeight);
  const glm::mat4 inverse = glm::inverse(camera.projectionMatrix(aspect) * camera.view());
  const glm::vec2 ndc{(float(x) + 0.5f) / float(kWidth) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(kHeight) * 2.0f};
  const glm::vec4 far = inverse * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 eye = camera.position(), dir = glm::normalize(glm::vec3(far) / far.w - eye);
  if (dir.y >= 0.0f) return std::nullopt;
  const glm::vec3 ground = eye + dir * (-eye.y / dir.y);
  return -(camera.view() * glm::vec4(ground, 1.0f)).z;
}

// The sun's maps this frame, as the renderer computes them.
std::vector<render::ShadowView> sunViews(const scene::Scene& s, const scene::Camera& camera) {
  std::vector<glm::vec4> spheres;
  for (const auto& instance : s.instances) {
    const auto b = scene::transformBounds(s.meshes[size_t(instance.mesh)].bounds, instance.world);
    spheres.emplace_back(b.center(), b.radius());
  }
  return render::shadowViews(s.lights, spheres,
                             {camera.view(), camera.projectionMatrix(float(kWidth) / float(kHeight)), camera.znear,
                              camera.zfar});
}

std::vector<float> endsOf(const std::vector<render::ShadowView>& views) {
  std::vector<float> ends;
  for (const auto& v : views) ends.push_back(v.cascadeEnd);
  return ends;
}

// Where a world point falls in a map, in texels.
glm::dvec2 texelOf(const render::ShadowView& v, const glm::vec3& p) {
  const glm::vec4 clip = v.viewProjection * glm::vec4(p, 1.0f);
  return (glm::dvec2(clip.x, clip.y) / double(clip.w) * 0.5 + 0.5) * double(render::kShadowMapResolution);
}

struct Band {
  double change = 0.0, squares = 0.0;
  size_t samples = 0;
  double mean() const { return samples ? change / double(samples) : 0.0; }
  double rms() const { return samples ? std::sqrt(squares / double(samples)) : 0.0; }
};

TEST(CascadeTransition, CascadesHoldTheirExtentsAndTexelsWhileTheCameraMoves) {
  const scene::Scene s = postField();
  StabilitySession session(s, scene::ShadingMode::Forward);
  const auto views0 = sunViews(s, cameraOfFrame(0));
  const auto ends0 = endsOf(views0);
  ASSERT_EQ(ends0.size(), size_t(render::kShadowCascades)) << "the sun has its cascades";
  const glm::vec3 anchor{0.3f, 0.0f, -5.0f}, step{1.0f, 0.0f, 0.0f};
  // The two hand-overs in view: cascade 0 to 1 and 1 to 2.
  std::vector<Band> before(2), boundary(2), after(2);
  std::vector<glm::vec4> last;
  for (int t = 0; t < kFrames; ++t) {
    const scene::Camera camera = cameraOfFrame(t);
    const auto views = sunViews(s, camera);
    const auto ends = endsOf(views);
    ASSERT_EQ(ends, ends0) << "frame " << t << ": the cascades' extents moved with the camera";
    for (size_t c = 0; c < views.size(); ++c) {
      // Compared with frame 0: a whole number of texels apart, and the same texels per unit.
      const glm::dvec2 moved = texelOf(views[c], anchor) - texelOf(views0[c], anchor);
      const glm::dvec2 span = texelOf(views[c], anchor + step) - texelOf(views[c], anchor);
      const glm::dvec2 span0 = texelOf(views0[c], anchor + step) - texelOf(views0[c], anchor);
      EXPECT_NEAR(moved.x, std::round(moved.x), 0.01) << "frame " << t << ", cascade " << c << ": its texels crawl";
      EXPECT_NEAR(moved.y, std::round(moved.y), 0.01) << "frame " << t << ", cascade " << c << ": its texels crawl";
      EXPECT_NEAR(glm::length(span), glm::length(span0), 1e-3 * glm::length(span0))
          << "frame " << t << ", cascade " << c << ": its texels changed size";
    }
    const StabilityFrame f = session.render(kWidth, kHeight, camera);
    expectFinite(f, "frame " + std::to_string(t));
    if (t == kFrames - 1) saveForInspection(f, "cascade_transition");
    if (t > 0) {
      double sum = 0.0;
      for (const auto& c : f.hdr) sum += double(luminance(c));
      const double mean = sum / double(f.hdr.size());
      for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
          const auto depth = groundDepth(camera, x, y);
          const size_t i = size_t(y) * kWidth + x;
          // Ground only, now and before (grey; a post is brown, red over blue above 1.4): shadows, not silhouettes.
          const auto ground = [](const glm::vec4& c) { return c.r < 1.4f * c.b; };
          if (!depth || !ground(f.hdr[i]) || !ground(last[i])) continue;
          const double change = std::abs(double(luminance(f.hdr[i])) - double(luminance(last[i]))) / mean;
          for (int b = 0; b < 2; ++b) {
            const float end = ends[b], start = b == 0 ? 0.0f : ends[b - 1];
            const float blend = shader::kCascadeBlend * (end - start), margin = 0.25f * blend;
            const float lo = end - blend - margin, hi = end + margin, width = hi - lo;
            Band* band = *depth >= lo && *depth <= hi                 ? &boundary[b]
                         : *depth >= lo - width && *depth < lo         ? &before[b]
                         : *depth > hi && *depth <= hi + width         ? &after[b]
                                                                       : nullptr;
            if (band) band->change += change, band->squares += change * change, ++band->samples;
          }
        }
    }
    last = f.hdr;
  }
  for (int b = 0; b < 2; ++b) {
    std::printf("cascade %d -> %d at view depth %.2f: mean |change| per frame %.5f before, %.5f at the boundary, "
                "%.5f after; rms %.5f, %.5f, %.5f (%zu, %zu, %zu pixel-frames)\n",
                b, b + 1, double(ends0[b]), before[b].mean(), boundary[b].mean(), after[b].mean(), before[b].rms(),
                boundary[b].rms(), after[b].rms(), before[b].samples,
                boundary[b].samples, after[b].samples);
    EXPECT_GT(boundary[b].samples, 500u) << "the boundary is not in view";
  }
}

}  // namespace
}  // namespace sg::test
