#pragma once
// Whether a frame's depth pre-pass pays for itself (issue 14: "a z-prepass
// only where overdraw pays for it"). The pre-pass rasterizes every opaque
// triangle a second time so that forward-opaque shades each pixel once; it
// saves the shading of the surfaces drawn first and covered later. On a CPU
// rasterizer the geometry costs per triangle and the shading per pixel, so
// the figure that decides is triangles per pixel: where the opaque triangles
// reach kZPrepassMaxTrianglesPerPixel, each covers a pixel or two,
// the pre-pass costs about as much as the shading it would save, and the frame
// draws without it (measured: docs/benchmarks.md, "Depth pre-pass").
#include <cstdint>

namespace sg::passes {

// Between 2CylinderEngine at 640x360 (0.53 a pixel, deep overdraw: the
// pre-pass saved 1.18x) and ReciprocatingSaw at 640x360 (0.86: without it
// 0.70x); MetalRoughSpheresNoTextures (1.13 at 1280x720) 0.66x without.
inline constexpr double kZPrepassMaxTrianglesPerPixel = 0.7;

// `opaqueTriangles`: of the frame's visible opaque draws; `pixels`: of the output.
bool zPrepassPays(uint64_t opaqueTriangles, uint64_t pixels);

}  // namespace sg::passes
