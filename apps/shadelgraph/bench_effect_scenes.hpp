#pragma once
// The scenes of `shadelgraph bench --effects`, generated in code (procedural
// meshes only: no asset needed) so each comparison changes one thing: how
// many of the same lights cast shadows, how many point lights there are,
// whether an environment image lights the set, whether an object glows.
#include <cstdint>
#include <filesystem>
#include <string>

#include <shadelgraph/scene/scene.hpp>

namespace sg::app {

// A courtyard (ground, boxes, a sphere, a cylinder) lit by `lights` lights of
// `type` placed around it, the first `shadowed` of them casting shadows.
// Directional lights are suns from different azimuths.
scene::Scene shadowBenchScene(scene::LightType type, uint32_t lights, uint32_t shadowed);

// A 14 x 10 floor with a back wall, crates and a sphere under `count` point
// lights on a jittered grid 0.35-0.85 above it, their range chosen so a floor
// point is within reach of about kLightsInReach of them at every count (the
// light each point gets stays about the same; only how many lights exist
// grows), none shadowed.
inline constexpr float kLightsInReach = 8.0f;
scene::Scene manyLightsBenchScene(uint32_t count);

// Spheres from rough to polished, dielectric and metal, on a ground plane,
// under an unshadowed sun; with `environment` (a Radiance .hdr) lit by it too.
scene::Scene iblBenchScene(const std::filesystem::path& environment = {});

// A small set under an unshadowed sun with a box emitting `emission` cd/m^2 in view.
scene::Scene bloomBenchScene(float emission);

// "directional", "spot", "point".
std::string lightTypeName(scene::LightType type);

}  // namespace sg::app
