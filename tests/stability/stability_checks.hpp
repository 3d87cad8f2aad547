#pragma once
// What every hard case asserts, and the one line of figures it prints:
// finite HDR pixels, a finite exposure, no composite misses, and agreement
// between two renders within a stated bound.
#include <string>

#include <shadelgraph/image/metrics.hpp>

#include "stability_session.hpp"

namespace sg::test {

struct HdrSummary {
  size_t nonFinite = 0;    // NaN or Inf in any channel
  float maxValue = 0.0f;   // largest finite channel value
  double exposure = 0.0;   // what the exposure pass computes from this image (passes/exposure/exposure.comp)
};
HdrSummary summarize(const std::vector<glm::vec4>& hdr);

// Agreement bound: PSNR at least `psnr` dB and mean |d| at most `meanAbs` /255.
struct Bound {
  double psnr = 30.0;
  double meanAbs = 2.0;
};

// No NaN/Inf in the HDR colour, a finite exposure in the pass's clamp range.
void expectFinite(const StabilityFrame& frame, const std::string& what);
// expectFinite, and (decoupled) no composite misses nor overflowing chunks.
void expectClean(const StabilityFrame& frame, const std::string& what);
// Compares two 8-bit outputs against `bound`, prints and records the figures.
image::ImageDifference expectAgreement(const StabilityFrame& a, const StabilityFrame& b, Bound bound,
                                       const std::string& what);

// Writes the frame's output to $SG_TEST_IMAGES/<name>.png when that is set (to look at it).
void saveForInspection(const StabilityFrame& frame, const std::string& name);

// Forward and decoupled renders of one scene from one camera.
struct BothPaths {
  StabilityFrame forward, decoupled;
};
BothPaths renderBothPaths(const scene::Scene& scene, uint32_t width, uint32_t height,
                          std::optional<scene::Camera> camera = {}, plugins::DecoupledSettings settings = {});

// Mean of the 8-bit output's RGB over all pixels, 0..255.
double meanLevel(const gpu::HostImage& image);

}  // namespace sg::test
