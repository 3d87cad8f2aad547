#pragma once
// A material layer: one GLSL function over a Surface (framework/plugin/shaders/surface.glsl,
// part of the material SDK a layer includes: framework/plugin/shaders/material.glsl)
// returning a vec4, plus what the framework needs to run it in either shading
// path. The framework generates the decoupled compute variant (one shadel per
// invocation) and the forward fragment variant (one pixel) from it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <shadelgraph/graph/resource_desc.hpp>

namespace sg::plugin {

// Which shading paths a layer can run in. A layer reading a neighbourhood
// (radius > 0) only exists in shadel space: it is DecoupledOnly, and a
// material using it names a forward fallback.
enum class LayerPaths : uint8_t { Both, DecoupledOnly, ForwardOnly };

// The layer reads `layer`'s value (sgLayer(name) / sgLayerAt(name, offset))
// up to `radius` shadels away at the same detail level.
struct LayerRead {
  std::string layer;
  uint32_t radius = 0;
};

// Neighbourhoods wider than one chunk would need more than the chunks next
// to the visible ones (support-expand grows by one chunk).
inline constexpr uint32_t kMaxLayerRadius = 8;

// A texture of the layer's own (a PNG, RGBA8, mip-mapped, linear filtering,
// repeat), bound as `uniform sampler2D <name>` in both variants. Sample it
// with textureGrad and the Surface's derivatives.
struct LayerTexture {
  std::string name;            // the GLSL sampler's name
  std::filesystem::path file;  // absolute, or relative to the working directory
  bool srgb = false;           // colour data (decoded to linear when sampled)
};

// A frame resource (an image some pass of the frame writes: "ao.image", a
// shadow map) the layer samples, bound as `uniform sampler2D <name>` in both
// variants. Screen-space images are sampled at sgScreenUv(s.position).
struct LayerFrameInput {
  std::string name;      // the GLSL sampler's name
  std::string resource;  // the frame resource
};

// What a layer's value depends on besides its material and the shadel's
// surface point: when a value kept from an earlier frame goes stale
// (docs/authoring-material-layers.md, "Layer rates").
enum class LayerDependence : uint8_t {
  View,     // the camera (specular, anything that reads frame.cameraPosition): shaded every shade frame
  World,    // the world pose and the lights, not the camera (diffuse lighting, a shadow term): kept until its object moves
  Surface,  // only the surface in texture or object space (a procedural albedo, a height field): kept even when it moves rigidly
};

// A kept (World or Surface) layer is recomputed anyway on every this-many-th shade frame.
inline constexpr uint32_t kDefaultRefreshShadeFrames = 8;

struct MaterialLayer {
  std::string name;      // unique, e.g. "height"; also the GLSL accessor name (letters, digits, '_', '-')
  std::string source;    // GLSL virtual path, e.g. "materials/height-normal/height.glsl"
  std::string function;  // vec4 function(Surface s) in that file
  // The layer image an intermediate layer writes; a material's last layer
  // writes the shaded colour (RGBA16F: radiance, alpha) that composite filters.
  graph::Format format = graph::Format::RGBA16F;
  std::vector<LayerRead> reads;  // earlier layers of the stack
  // Keeps last frame's values: sgPrevious(out vec4) returns them where the
  // shadel existed last frame (decoupled; the forward variant always computes).
  bool persistent = false;
  LayerPaths paths = LayerPaths::Both;
  // View (default): shaded whenever its chunk is. World or Surface: view-independent,
  // its decoupled values are kept across shade frames while their inputs hold
  // (an intermediate layer keeps a layer image of its own), and recomputed every
  // `refreshShadeFrames` shade frames (1 or more).
  LayerDependence dependsOn = LayerDependence::View;
  uint32_t refreshShadeFrames = kDefaultRefreshShadeFrames;
  std::vector<std::pair<std::string, std::string>> parameters;  // #define name value, before the source
  std::vector<LayerTexture> textures;
  std::vector<LayerFrameInput> frameInputs;
  std::string plugin;  // who registered it (set by the registry; named in errors)

  bool viewIndependent() const { return dependsOn != LayerDependence::View; }
  // Has a history image pair and reads last frame's values (sgPrevious).
  bool keepsValues() const { return persistent || viewIndependent(); }
  uint32_t radius() const {
    uint32_t r = 0;
    for (const auto& read : reads) r = read.radius > r ? read.radius : r;
    return r;
  }
};

}  // namespace sg::plugin
