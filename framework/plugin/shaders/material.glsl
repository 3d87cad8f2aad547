// The material SDK: what a material layer (or a plugin's shader) includes.
//   #include <framework/plugin/shaders/material.glsl>
// gives
//   - Surface: the point being shaded, with its UV and position derivatives
//     (surface.glsl);
//   - frame: the frame uniforms (camera, ambient, output size, lights; set 0,
//     binding 0) and sgScreenUv(worldPosition) (framework/render/shaders/frame.glsl);
//   - sgLightsAt(position), sgLight(list, k), sgLightAt(light, position): the
//     lights that may reach a point, and direction to one and the
//     radiance it delivers there; SG_PI (lights.glsl);
//   - sgEnvironmentDiffuse / sgEnvironmentSpecular / sgEnvironmentBrdf: the
//     scene's environment light when frame.environment.x > 0 (environment.glsl);
//   - material, materialHas, materialSample(texture, slot, s): the object's
//     scene material (glTF constants and textures, set 1) sampled with the
//     surface's derivatives (scene_material.glsl).
// Installed with the package under include/shadelgraph/glsl/ by these same
// paths; the runtime compiles its embedded copies. Every file has an include
// guard, so including it again (a generated shader already did) is harmless.
#ifndef SG_MATERIAL_SDK_GLSL
#define SG_MATERIAL_SDK_GLSL

#include <framework/render/shaders/frame.glsl>
#include <framework/plugin/shaders/surface.glsl>
#include <framework/plugin/shaders/lights.glsl>
#include <framework/plugin/shaders/environment.glsl>
#include <framework/plugin/shaders/scene_material.glsl>

#endif
