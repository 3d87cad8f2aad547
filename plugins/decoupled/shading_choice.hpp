#pragma once
// Which instances are shaded decoupled and which forward, and why: the
// per-object mode (glTF extras, scene file, or --mode for all), the shading
// chart, and what the decoupled path supports so far. Meshes that will be
// shaded decoupled but have no unique chart get an automatic one (in uv1)
// when the mode is `decoupled`; `auto` only takes objects that already have one.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::plugins {

struct ShadingChoice {
  uint32_t instance = 0;
  bool eligible = false;   // has what decoupled shading needs (a unique chart...), whatever its mode
  bool decoupled = false;  // eligible and not forward by request at load
  bool automatic = false;  // mode auto: forward in frames where the object is tiny on screen
  std::string reason;  // why forward, or how decoupled ("unique TEXCOORD_0", "automatic chart: 212 charts")
  int uvSet = -1;      // shading chart
  glm::vec2 tileOffset{0.0f};
};

// May replace meshes of `scene` by auto-charted copies (only of objects in
// mode decoupled: charting changes the uploaded geometry, so an object
// switched to decoupled later needs a chart of its own). `override`: --mode.
std::vector<ShadingChoice> chooseShading(scene::Scene& scene, std::optional<scene::ShadingMode> override);

}  // namespace sg::plugins
