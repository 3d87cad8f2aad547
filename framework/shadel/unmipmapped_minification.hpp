#pragma once
// Whether decoupled shading can reproduce a texture that has no mip levels in
// a given view. Forward reads such a texture at every pixel from its full
// resolution. A shadel of level L reads it once at the shadel's centre, and
// composite filters the shadels again: where the texture is minified (texels
// smaller than pixels), composite reads a level coarser than the texels, so
// the texels between shadel centres are lost (aliased at the shadel rate) and
// the rest blurred (TextureTransformTest at 640x360: thin lines and letter
// edges; 33.6 dB against forward, 35.3 against a 16-sample reference where
// forward is 39.2). With mip levels the shadel reads the level's mip and
// nothing is lost; without them only shadels at least as dense as the texels
// would hold the texture, at more than one shadel per pixel where forward
// shades one. So auto mode draws such an object forward in the frames where
// its texture is minified (decoupled_shading.cpp, selectFrameObjects).
#include <string>

#include <shadelgraph/scene/scene.hpp>

namespace sg::shadel {

// Up to this many texels per pixel composite still reads level 0 (its nearest
// rounding: level 0 up to half a level minified), where the level-0 shadels
// hold the texture's texels when level 0 is the texture's density.
inline constexpr double kMaxUnmipmappedTexelsPerPixel = 1.41421356237;

// The finest texture without mip levels the mesh's materials sample: its texels
// per object-space length unit (mean over the mesh: texture size, times its
// KHR_texture_transform scale, times sqrt(UV area / surface area) of its UV
// set). texelsPerUnit 0: none such (or no UV area).
struct UnmipmappedTexels {
  double texelsPerUnit = 0.0;
  std::string texture;  // its name, for the verdict
};
UnmipmappedTexels unmipmappedTexels(const scene::Scene& scene, const scene::Mesh& mesh);

// Texels per pixel of that texture on an object drawn with a uniform world
// scale `worldScale` at `distance` from the camera, in a view with
// `pixelsPerUnitAtUnitDistance` (the projection's pixels per world unit at
// distance 1). 0 when there is no such texture or no view.
double unmipmappedTexelsPerPixel(const UnmipmappedTexels& texels, double worldScale, double distance,
                                 double pixelsPerUnitAtUnitDistance);

}  // namespace sg::shadel
