// Flicker at a directional light's cascade boundaries (issue 16: "a directional
// cascade transition with a moving camera"), measured where it is world-stable:
// an orthographic camera dollies along its own axis over a ground striped by
// the shadow of a slatted roof above the view (thin slats: shadow edges every
// few texels). Moved along its axis, an orthographic camera sees every world
// point at the same pixel in every frame while the point's view depth, and so
// its cascade and blend weight, changes: a pixel's frame-to-frame change is
// the shading's own flicker, never motion across pixels. Asserted: away from
// the boundaries a point does not change (snapped, constant-size cascades:
// without the snap it changes 30x more); where a boundary crosses a point, the
// point moves from the far cascade's shadow to the near one's evenly over the
// blend band, never more than its share in one frame (without the blend it
// moves all at once). A point at a boundary does change while one away does
// not: the cascades filter a thin shadow at different resolutions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
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
constexpr int kFrames = 41;
constexpr float kStep = 0.04f;                     // dolly per frame (a walk at 60 Hz is about 0.025)
constexpr float kPitch = glm::radians(8.0f);       // the camera looks down 8°: view depth spans 0.6 to 8
constexpr float kHalfHeight = 0.4f;                // orthographic half height
constexpr float kFar = 16.0f;                      // fixes the cascades' far end (the ground reaches past it)

float luminance(const glm::vec4& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// A grey ground under a roof of thin slats, 2 units up and out of the camera's view, at 30° to its path.
scene::Scene slattedRoof() {
  scene::Scene s;
  const int ground = addMaterial(s, {.name = "ground", .baseColorFactor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f),
                                     .metallicFactor = 0.0f, .roughnessFactor = 1.0f});
  const int slat = addMaterial(s, {.name = "slat", .baseColorFactor = glm::vec4(0.4f, 0.3f, 0.2f, 1.0f),
                                   .metallicFactor = 0.0f, .roughnessFactor = 1.0f});
  placeMesh(s, scene::makePlane(80.0f, 80.0f, 8), ground, glm::mat4(1.0f));
  for (int i = -40; i <= 40; ++i) {
    const glm::mat4 world = glm::rotate(glm::translate(glm::mat4(1.0f), {float(i) * 0.11f, 2.0f, -6.0f}),
                                        glm::radians(30.0f), {0.0f, 1.0f, 0.0f});
    placeMesh(s, scene::makeBox({0.025f, 0.025f, 20.0f}), slat, world);
  }
  s.lights.push_back({.name = "sun", .type = scene::LightType::Directional, .intensity = 1e3f,
                      .direction = glm::normalize(glm::vec3(-0.3f, -1.0f, 0.4f))});
  return s;
}

// Frame t: the camera moved t steps along its axis; its centre ray meets the ground at view depth 5.2 - t * step.
scene::Camera cameraOfFrame(int t) {
  const glm::vec3 forward{0.0f, -std::sin(kPitch), -std::cos(kPitch)};
  const glm::vec3 eye = -forward * 5.2f + forward * (float(t) * kStep);
  scene::Camera c = cameraAt(eye, eye + forward, 0.1f, kFar);
  c.projection = scene::Projection::Orthographic;
  c.ymag = kHalfHeight;
  return c;
}

// The view depth of the ground point pixel (x, y) sees.
float groundDepth(const scene::Camera& camera, uint32_t x, uint32_t y) {
  const float aspect = float(kWidth) / float(kHeight);
  const glm::mat4 inverse = glm::inverse(camera.projectionMatrix(aspect) * camera.view());
  const glm::vec2 ndc{(float(x) + 0.5f) / float(kWidth) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(kHeight) * 2.0f};
  const glm::vec4 a = inverse * glm::vec4(ndc, 0.0f, 1.0f), b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
  const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
  const glm::vec3 ground = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
  return -(camera.view() * glm::vec4(ground, 1.0f)).z;
}

std::vector<float> cascadeEndsOf(const scene::Scene& s, const scene::Camera& camera) {
  std::vector<glm::vec4> spheres;
  for (const auto& instance : s.instances) {
    const auto b = scene::transformBounds(s.meshes[size_t(instance.mesh)].bounds, instance.world);
    spheres.emplace_back(b.center(), b.radius());
  }
  const auto views = render::shadowViews(
      s.lights, spheres,
      {camera.view(), camera.projectionMatrix(float(kWidth) / float(kHeight)), camera.znear, camera.zfar});
  std::vector<float> ends;
  for (const auto& v : views) ends.push_back(v.cascadeEnd);
  return ends;
}

// Luminance over the frame's mean, and the view depth its ground point had, per pixel of every frame.
struct Sequence {
  std::vector<std::vector<float>> level, depth;
};

// What one boundary did to the pixels it crossed: each crossed it wholly
// during the walk (from beyond the boundary to nearer than its blend band),
// changing by |D| from the far cascade's shadow to the near one's. A fade over
// the band moves a pixel at most step/band of |D| a frame; a pop moves it all of |D| at once.
struct Handover {
  double largestSteps = 0.0, changes = 0.0;  // sums over the crossed pixels: largest frame-to-frame change, |D|
  size_t pixels = 0;
  double ratio() const { return changes > 0.0 ? largestSteps / changes : 0.0; }
};

Handover handoverAt(const Sequence& seq, float end, float band) {
  Handover h;
  const size_t pixels = seq.level.front().size();
  for (size_t i = 0; i < pixels; ++i) {
    int before = -1, after = -1;  // the last frame beyond the boundary, the first nearer than its band
    for (size_t t = 0; t < seq.level.size(); ++t) {
      if (seq.depth[t][i] > end) before = int(t);
      if (after < 0 && seq.depth[t][i] < end - band) after = int(t);
    }
    if (before < 0 || after <= before) continue;
    const double change = std::abs(double(seq.level[size_t(after)][i]) - double(seq.level[size_t(before)][i]));
    if (change < 0.05) continue;  // the two cascades agree here (inside a stripe or between them)
    double largest = 0.0;
    for (int t = before; t < after; ++t)
      largest = std::max(largest, std::abs(double(seq.level[size_t(t + 1)][i]) - double(seq.level[size_t(t)][i])));
    h.largestSteps += largest, h.changes += change, ++h.pixels;
  }
  return h;
}

// Mean frame-to-frame change of the pixels whose ground point stays in the
// middle half of one cascade (clear of every blend band) in both frames.
double changeAwayFromBoundaries(const Sequence& seq, const std::vector<float>& ends) {
  double sum = 0.0;
  size_t samples = 0;
  const auto inMiddle = [&](float depth) {
    for (size_t c = 0; c < ends.size(); ++c) {
      const float lo = c == 0 ? 0.0f : ends[c - 1], q = 0.25f * (ends[c] - lo);
      if (depth > lo + q && depth < ends[c] - q) return true;
    }
    return false;
  };
  for (size_t t = 1; t < seq.level.size(); ++t)
    for (size_t i = 0; i < seq.level[t].size(); ++i)
      if (inMiddle(seq.depth[t][i]) && inMiddle(seq.depth[t - 1][i]))
        sum += std::abs(double(seq.level[t][i]) - double(seq.level[t - 1][i])), ++samples;
  EXPECT_GT(samples, 10000u) << "too little ground away from the boundaries";
  return samples ? sum / double(samples) : 0.0;
}

TEST(CascadeFlicker, AWorldPointChangesOnlyAsTheBlendBandCrossesIt) {
  const scene::Scene s = slattedRoof();
  StabilitySession session(s, scene::ShadingMode::Forward);
  const auto ends = cascadeEndsOf(s, cameraOfFrame(0));
  ASSERT_EQ(ends.size(), size_t(render::kShadowCascades)) << "the sun has its cascades";
  Sequence seq;
  for (int t = 0; t < kFrames; ++t) {
    const scene::Camera camera = cameraOfFrame(t);
    ASSERT_EQ(cascadeEndsOf(s, camera), ends) << "frame " << t << ": the cascades' extents moved";
    const StabilityFrame f = session.render(kWidth, kHeight, camera);
    expectFinite(f, "frame " + std::to_string(t));
    if (t == kFrames / 2) saveForInspection(f, "cascade_flicker");
    double sum = 0.0;
    for (const auto& c : f.hdr) sum += double(luminance(c));
    const float mean = float(sum / double(f.hdr.size()));
    std::vector<float> level(f.hdr.size()), depth(f.hdr.size());
    for (uint32_t y = 0; y < kHeight; ++y)
      for (uint32_t x = 0; x < kWidth; ++x) {
        const size_t i = size_t(y) * kWidth + x;
        level[i] = luminance(f.hdr[i]) / mean;
        depth[i] = groundDepth(camera, x, y);
      }
    seq.level.push_back(std::move(level));
    seq.depth.push_back(std::move(depth));
  }
  // Away from the boundaries a world point's shadow holds still (snapped, constant-size cascades).
  const double away = changeAwayFromBoundaries(seq, ends);
  std::printf("away from the boundaries: mean |change| per frame %.5f of the mean level\n", away);
  EXPECT_LT(away, 1e-3) << "the shadow changes under a still world point: the cascades' texels crawl";
  // At a boundary, the hand-over is spread over its blend band: no frame takes more than its share.
  for (int b = 0; b + 1 < int(ends.size()); ++b) {
    const float band = shader::kCascadeBlend * (ends[b] - (b == 0 ? 0.0f : ends[b - 1]));
    const Handover h = handoverAt(seq, ends[b], band);
    const double share = double(kStep / band);
    std::printf("cascade %d -> %d at view depth %.2f (band %.3f): %zu pixels crossed it, changing %.3f on average; "
                "their largest change in one frame is %.3f of that (a fade over the band: %.3f, a pop: 1)\n",
                b, b + 1, double(ends[b]), double(band), h.pixels, h.pixels ? h.changes / double(h.pixels) : 0.0,
                h.ratio(), share);
    if (b < 2) {
      EXPECT_GT(h.pixels, 100u) << "boundary " << b << " crossed too few shadow edges";
    }
    if (h.pixels) {
      EXPECT_LT(h.ratio(), 1.25 * share + 0.02) << "boundary " << b << " pops instead of fading";
    }
  }
}

}  // namespace
}  // namespace sg::test
