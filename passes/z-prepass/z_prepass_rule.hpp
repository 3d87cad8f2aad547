#pragma once
// Whether a frame's depth pre-pass pays for itself (issue 14: "a z-prepass
// only where overdraw pays for it"). The pre-pass sends every opaque triangle
// through the rasterizer a second time so that forward-opaque shades each
// pixel once; it saves the shading of the fragments drawn first and covered
// later. Triangles per pixel cannot see that overdraw (ReciprocatingSaw at
// 0.22 a pixel gains nothing, 2CylinderEngine at 0.13 does), so the decision
// uses the overdraw measured once (z_prepass_choice.hpp): the fragments that
// pass the depth test as drawn (what forward-opaque shades without the
// pre-pass) against those forward-opaque shades after it (about one a covered
// pixel), priced against the triangles drawn again (docs/benchmarks.md,
// "Depth pre-pass").
#include <cstdint>

#include <glm/glm.hpp>

namespace sg::passes {

// What a measurement frame (drawn with the pre-pass) counted.
struct Overdraw {
  uint64_t triangles = 0;    // opaque triangles of the visible forward draws
  uint64_t depthPassed = 0;  // fragments passing the pre-pass's depth test as drawn: shaded without it
  uint64_t shaded = 0;       // fragments forward-opaque shaded against its depth (about the covered pixels)
  // Textures an opaque triangle's material samples, on average over the
  // triangles: a textured fragment costs more to shade (DamagedHelmet's five).
  double texturesPerTriangle = 0.0;
  // Fragments forward-opaque would shade without the pre-pass per covered pixel (1: no overdraw).
  double depthComplexity() const { return shaded ? double(depthPassed) / double(shaded) : 0.0; }
  uint64_t overdrawn() const { return depthPassed > shaded ? depthPassed - shaded : 0; }
};

// The cost model, in an untextured fragment's shading: a triangle the
// pre-pass draws again (vertex shading, setup, binning, a depth-only raster)
// costs about kZPrepassFragmentsPerTriangle overdrawn fragments; each texture
// the material samples adds kZPrepassShadingPerTexture to a fragment.
// Fitted by callgrind (lavapipe, one thread) on 2CylinderEngine at 1280x720
// (3.1 overdrawn a triangle, 9% more instructions without the pre-pass) and
// 640x360 (0.78, 8% fewer without), untextured: 595 instructions a triangle,
// 394 a fragment; the texture weight by DamagedHelmet at 1280x720 (five
// textures, 1.26 overdrawn a triangle, 4.6% more without: 1316 a fragment)
// (docs/benchmarks.md, "Depth pre-pass from measured overdraw").
inline constexpr double kZPrepassFragmentsPerTriangle = 1.5;
inline constexpr double kZPrepassShadingPerTexture = 0.5;

bool zPrepassPays(const Overdraw& measured);

// When a measurement stops describing the frame: what it was measured on.
struct OverdrawView {
  uint32_t width = 0, height = 0;
  uint64_t triangles = 0;  // as Overdraw::triangles
  double texturesPerTriangle = 0.0;
  glm::mat4 viewProjection{1.0f};
};

// The output size changed, the visible opaque triangles by more than an
// eighth, or the camera by more than a tenth of its view-projection (relative
// Frobenius norm): overdraw may differ, measure again. A camera that moves a
// little each frame is measured again only when it has moved that far since.
bool overdrawStale(const OverdrawView& measured, const OverdrawView& now);

}  // namespace sg::passes
