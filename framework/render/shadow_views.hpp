#pragma once
// Shadow-map views of the scene's lights: which lights get a map (shadowed
// spot lights, one slot of the shadow atlas each, in light order), each map's
// view-projection fitted to the draws the light reaches, and whether a light
// reaches a bounding sphere at all. The frame uniforms carry the matrices and
// slots; passes/shadows renders the maps of lights that reach a visible draw.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/light.hpp>

namespace sg::render {

inline constexpr uint32_t kShadowMapResolution = 1024;  // texels per side of one map

struct ShadowView {
  uint32_t light = 0;  // index into the lights
  uint32_t slot = 0;   // the map's column in the atlas
  glm::mat4 viewProjection{1.0f};  // world to the map's clip space (depth 0..1, +Y up like the cameras)
};

// Whether the light can deliver any light into the sphere (xyz centre, w radius):
// conservative (true when unsure), by range and, for spots, by the cone.
bool lightReaches(const scene::Light& light, const glm::vec4& sphere);

// The maps the lights get (`spheres`: every draw's world bounding sphere, which
// the depth range is fitted to). At most `maxMaps`; lights after that stay unshadowed.
std::vector<ShadowView> shadowViews(std::span<const scene::Light> lights, std::span<const glm::vec4> spheres,
                                    uint32_t maxMaps);

}  // namespace sg::render
