#pragma once
// Shadow-map views of the scene's lights: which lights get maps (shadowed
// lights that reach an object in the camera's view), how many (a spot 1, a
// point light 6 cube faces, a directional light kShadowCascades cascades),
// their slots in the shadow atlas and view-projections, and whether a light
// reaches a bounding sphere at all. Computed once per frame (Renderer); the
// frame uniforms carry the matrices and slots, passes/shadows renders the maps.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/render/shaders/frame_interface.h>
#include <shadelgraph/scene/light.hpp>

namespace sg::render {

inline constexpr uint32_t kShadowMapResolution = 1024;  // texels per side of one map
using shader::kMaxShadowMaps;
using shader::kShadowAtlasColumns;
using shader::kShadowCascades;

struct ShadowView {
  uint32_t light = 0;  // index into the lights
  uint32_t slot = 0;   // the map's place in the atlas (column slot % kShadowAtlasColumns, row slot / kShadowAtlasColumns)
  uint32_t face = 0;   // which of the light's maps: cascade (near to far) or cube face (+X -X +Y -Y +Z -Z); 0 for a spot
  glm::mat4 viewProjection{1.0f};  // world to the map's clip space (depth 0..1, +Y up like the cameras)
  float cascadeEnd = 0.0f;         // directional: the view depth where this cascade ends
};

// What the directional cascades are fitted to, and what counts as visible.
struct ShadowCamera {
  glm::mat4 view{1.0f}, projection{1.0f};  // the camera's (projection: clip depth 0..1)
  float znear = 0.1f;
  std::optional<float> zfar;  // absent: infinite
};

// Whether the light can deliver any light into the sphere (xyz centre, w radius):
// conservative (true when unsure), by range and, for spots, by the cone.
bool lightReaches(const scene::Light& light, const glm::vec4& sphere);

// The maps the lights get (`spheres`: every draw's world bounding sphere).
// A shadowed light gets its maps only when it reaches a sphere inside the
// camera's frustum; lights are served in order while kMaxShadowMaps slots last
// (a light whose maps do not all fit stays unshadowed).
std::vector<ShadowView> shadowViews(std::span<const scene::Light> lights, std::span<const glm::vec4> spheres,
                                    const ShadowCamera& camera);

// The draws (indices into `spheres`) a view's map holds: those its light reaches inside the view's frustum.
bool castsInto(const ShadowView& view, const scene::Light& light, const glm::vec4& sphere);

// Whether a caster's shadow from the light may fall on a receiver (spheres):
// the receiver meets the caster's shadow volume (a cylinder along a
// directional light, a cone from a point or spot light). Conservative.
bool shadowMayFallOn(const scene::Light& light, const glm::vec4& caster, const glm::vec4& receiver);

// The atlas's extent in maps: columns and rows for `maps` maps.
glm::uvec2 shadowAtlasMaps(uint32_t maps);

}  // namespace sg::render
