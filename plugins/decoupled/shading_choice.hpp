#pragma once
// Which instances are shaded decoupled and which forward, and why: the
// per-object mode (glTF extras, scene file, or --mode for all), the shading
// chart, and what the decoupled path supports so far. Meshes that will be
// shaded decoupled but have no unique chart get an automatic one (in uv1)
// when the mode is `decoupled`; `auto` only takes objects that already have one.
//
// Each primitive of a mesh is a decoupled object of its own (its draw, its
// material, its own shadel space and triangle-ID map): primitives of one mesh
// usually map their UVs over the same [0,1]² (one texture set per material),
// so one shadel space for the whole mesh would have them overlap
// (docs/decoupled-shading.md, "Multi-primitive meshes").
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::plugins {

// One primitive's verdict: its chart, or why it stays forward.
struct PrimitiveChoice {
  bool eligible = false;  // has what decoupled shading needs (a unique chart, an opaque or alpha-mask material)
  std::string reason;     // why forward, or how decoupled ("unique TEXCOORD_0")
  int uvSet = -1;         // shading chart
  glm::vec2 tileOffset{0.0f};
  bool automaticChart = false;  // uvSet is a chart made for shading (mode decoupled), not the mesh's own UVs
};

struct ShadingChoice {
  uint32_t instance = 0;
  // Every primitive the decoupled path takes (all but alpha-blended ones) is
  // eligible, and there is at least one, whatever the object's mode.
  bool eligible = false;
  bool decoupled = false;  // eligible and not forward by request at load
  bool automatic = false;  // mode auto: forward in frames where the object is tiny on screen
  // Why forward, or how decoupled ("unique TEXCOORD_0", "automatic chart: 212
  // charts"); a multi-primitive object's says it per primitive when they differ.
  std::string reason;
  std::vector<PrimitiveChoice> primitives;  // by primitive of the instance's mesh
};

// Primitive `p` of `mesh` as a mesh of its own (the decoupled object's
// geometry: its chart, density and triangle-ID map are computed on it).
scene::Mesh primitiveMesh(const scene::Mesh& mesh, size_t p);

// The alpha mode's part of a primitive's verdict: empty when decoupled shading
// takes the material (opaque; alpha-mask: shadel-mark and composite alpha-test),
// else why not (alpha-blend: what is behind shows through, shaded forward).
std::string alphaModeRefusal(const scene::Material& material);

// One line for an object from its primitives' verdicts: the shared reason, or
// "primitive N: reason" for each when they differ.
std::string objectReason(const std::vector<PrimitiveChoice>& primitives);

// May replace meshes of `scene` by auto-charted copies (only of objects in
// mode decoupled: charting changes the uploaded geometry, so an object
// switched to decoupled later needs a chart of its own). `override`: --mode.
std::vector<ShadingChoice> chooseShading(scene::Scene& scene, std::optional<scene::ShadingMode> override);

// What `inspect` prints and `render --stats` writes for an object: "decoupled"
// or "forward" as chosen at load and why, then each primitive's when it has several.
struct ShadingReport {
  std::string shading;
  std::string reason;
  std::vector<ShadingReport> primitives;  // empty for a one-primitive object
};
ShadingReport shadingReport(const ShadingChoice& choice);
// The report as text: "object 'NAME': shading (reason)", then "  primitive N: shading (reason)" lines.
std::string shadingReportLines(const std::string& name, const ShadingReport& report);

}  // namespace sg::plugins
