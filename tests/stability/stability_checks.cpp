#include "stability_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <shadelgraph/image/png.hpp>

namespace sg::test {

HdrSummary summarize(const std::vector<glm::vec4>& hdr) {
  HdrSummary s;
  double logSum = 0.0;
  for (const glm::vec4& p : hdr) {
    bool finite = true;
    for (int c = 0; c < 4; ++c) {
      if (!std::isfinite(p[c])) {
        finite = false;
      } else {
        s.maxValue = std::max(s.maxValue, p[c]);
      }
    }
    if (!finite) ++s.nonFinite;
    const double luminance = 0.2126 * double(p.r) + 0.7152 * double(p.g) + 0.0722 * double(p.b);
    logSum += std::log(std::max(luminance, 1e-4));  // Inf stays Inf, NaN stays NaN: as on the GPU
  }
  const double logAverage = hdr.empty() ? 0.0 : logSum / double(hdr.size());
  // The pass's default metering range, EV100 -3.585 to 24, is an exposure of 10 down to 1 / (1.2 * 2^24);
  // a NaN log-average would give NaN here.
  const double lowest = 1.0 / (1.2 * std::exp2(24.0));
  s.exposure = std::isnan(logAverage) ? logAverage : std::clamp(0.18 / std::exp(logAverage), lowest, 10.0);
  return s;
}

void expectFinite(const StabilityFrame& frame, const std::string& what) {
  ASSERT_EQ(frame.hdr.size(), size_t(frame.ldr.width) * frame.ldr.height) << what << ": HDR readback missing";
  const HdrSummary s = summarize(frame.hdr);
  EXPECT_EQ(s.nonFinite, 0u) << what << ": NaN/Inf pixels in the HDR colour";
  EXPECT_TRUE(std::isfinite(s.exposure)) << what << ": exposure " << s.exposure;
}

void expectClean(const StabilityFrame& frame, const std::string& what) {
  expectFinite(frame, what);
  EXPECT_EQ(frame.stats.counters.compositeMisses, 0u) << what;
  EXPECT_EQ(frame.stats.counters.overflowChunks, 0u) << what;
}

image::ImageDifference expectAgreement(const StabilityFrame& a, const StabilityFrame& b, Bound bound,
                                       const std::string& what) {
  const auto d = image::compareRgba8(a.ldr.rgba8, b.ldr.rgba8);
  std::printf("%-44s PSNR %6.2f dB  mean |d| %5.2f/255  max |d| %3d  >8/255 %5.2f%%\n", what.c_str(), d.psnr,
              d.meanAbs, d.maxAbs, 100.0 * d.fractionAbove8);
  ::testing::Test::RecordProperty(what + " psnr", std::to_string(d.psnr));
  EXPECT_GE(d.psnr, bound.psnr) << what;
  EXPECT_LE(d.meanAbs, bound.meanAbs) << what;
  return d;
}

void saveForInspection(const StabilityFrame& frame, const std::string& name) {
  if (const char* dir = std::getenv("SG_TEST_IMAGES"))
    image::writePng(std::string(dir) + "/" + name + ".png", frame.ldr.width, frame.ldr.height,
                    frame.ldr.rgba8.data());
}

BothPaths renderBothPaths(const scene::Scene& scene, uint32_t width, uint32_t height,
                          std::optional<scene::Camera> camera, plugins::DecoupledSettings settings) {
  BothPaths out;
  {
    StabilitySession f(scene, scene::ShadingMode::Forward);
    out.forward = f.render(width, height, camera);
  }
  {
    StabilitySession d(scene, scene::ShadingMode::Decoupled, settings);
    out.decoupled = d.render(width, height, camera);
    EXPECT_GT(out.decoupled.stats.objects, 0u) << "nothing was shaded decoupled";
  }
  return out;
}

double meanLevel(const gpu::HostImage& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.rgba8.size(); i += 4) sum += image.rgba8[i] + image.rgba8[i + 1] + image.rgba8[i + 2];
  return sum / (3.0 * double(image.width) * image.height);
}

}  // namespace sg::test
