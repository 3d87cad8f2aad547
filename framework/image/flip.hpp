#pragma once
// ꟻLIP, the LDR variant: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström, Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020, with the constants of NVIDIA's
// reference implementation (NVlabs/flip).
//
// Both images are sRGB-encoded 8-bit RGBA (alpha ignored). Per pixel the error is in [0, 1]:
//   colour pipeline: sRGB -> linear RGB -> XYZ -> YCxCz; each channel is filtered with its contrast
//     sensitivity function (a sum of Gaussians a1·sqrt(pi/b1)·exp(-pi²r²/b1) + a2·sqrt(pi/b2)·exp(-pi²r²/b2),
//     r in degrees; A: 1, 0.0047, 0, 1e-5; RG: 1, 0.0053, 0, 1e-5; BY: 34.1, 0.04, 13.5, 0.025) over a
//     radius of ceil(3·sqrt(0.04 / (2 pi²))·ppd) pixels, borders clamped; the result is clamped to the linear
//     RGB cube, taken to CIELAB, Hunt-adjusted (a, b scaled by 0.01·L) and compared with HyAB
//     (|ΔL| + ||(Δa, Δb)||). ΔE_c = HyAB^0.7, remapped so [0, 0.4·cmax) -> [0, 0.95) linearly and
//     [0.4·cmax, cmax] -> [0.95, 1], cmax = HyAB(Hunt green, Hunt blue)^0.7.
//   feature pipeline: on the luminance Y/Yn, edge (first derivative) and point (second derivative) detectors
//     of a Gaussian with std dev 0.5·0.082·ppd px (radius ceil(3 sd)), positive and negative weights each
//     normalised to ±1; ΔE_f = (max(| |edge_ref| - |edge_test| |, | |point_ref| - |point_test| |) / sqrt 2)^0.5.
//   error = ΔE_c^(1 - ΔE_f).
// Every filter is applied separably, which equals the reference's 2D filters up to float rounding, and the
// zero-sum detectors are applied to differences from the centre pixel, so that flat regions have exactly no
// features (float residue there would otherwise be magnified by the square root in ΔE_f).
// The measure is symmetric: flipLdr(a, b) and flipLdr(b, a) give the same map.
#include <shadelgraph/image/png.hpp>

#include <cstdint>
#include <numbers>
#include <vector>

namespace sg::image {

// The reference implementation's default observer: a 0.7 m wide monitor 3840 pixels across, seen from
// 0.7 m: 0.7 · (3840 / 0.7) · pi / 180 ≈ 67.02 pixels per degree.
inline constexpr double kFlipDefaultPixelsPerDegree = 0.7 * (3840.0 / 0.7) * std::numbers::pi / 180.0;

struct FlipResult {
  std::vector<float> errorMap;  // width * height, rows top to bottom, each in [0, 1]
  uint32_t width = 0, height = 0;
  double mean = 0.0;
  double median = 0.0;          // of the per-pixel errors (the mean of the middle two for an even count)
  double weightedMedian = 0.0;  // the error splitting the error *sum* in half, as the reference tool reports it
  double max = 0.0;
};

// Throws std::invalid_argument if the images differ in size or a pixel buffer does not match its size.
FlipResult flipLdr(const Rgba8Image& reference, const Rgba8Image& test,
                   double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

// The error map through the magma colour map (error e -> entry round(255·e)), as the reference tool draws it.
Rgba8Image flipHeatmap(const FlipResult& result);

// The sRGB transfer function's decode (IEC 61966-2-1) of an 8-bit value, as FLIP uses it.
float srgbToLinear(uint8_t encoded);

}  // namespace sg::image
