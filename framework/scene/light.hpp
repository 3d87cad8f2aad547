#pragma once
// KHR_lights_punctual lights, placed in world space.
#include <numbers>
#include <string>

#include <glm/glm.hpp>

namespace sg::scene {

enum class LightType { Directional, Point, Spot };

struct Light {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};   // linear RGB
  float intensity = 1.0f;  // candela (point, spot) or lux (directional), as the extension defines
  float range = 0.0f;      // 0: infinite
  float innerConeAngle = 0.0f;                          // spot only, radians
  float outerConeAngle = std::numbers::pi_v<float> / 4;  // spot only, radians
  glm::vec3 position{0.0f};                             // world space; unused for directional
  glm::vec3 direction{0.0f, 0.0f, -1.0f};               // world space, unit; the light's -Z
  bool shadows = true;  // casts shadows (scene file "shadows", glTF light extras.shadows)
};

}  // namespace sg::scene
