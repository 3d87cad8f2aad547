#pragma once
// Scenes the hard cases are built from, made in code: a small lit set
// (textured, normal-mapped crate and sphere on a tiled ground; a sun and a
// lamp), single-mesh scenes for the geometry cases, and whole-scene moves.
#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>

namespace sg::test {

// The set around the origin, about 8 units across, with its camera.
scene::Scene makeLitSet(uint32_t textureSize = 128);

// The lit set with its lights replaced by `count` point lights on a grid over
// the ground (0.2 to 0.7 above it, range 1.2: a ground point is within reach
// of about 20 of 300), each of its own colour.
scene::Scene makeLitSetWithPointLights(uint32_t count);

// A scene holding only `mesh` (one primitive) with a tiles material (colour
// and normal map), lit by a sun from above-front and a lamp; no camera.
scene::Scene makeSingleMesh(scene::Primitive mesh, uint32_t textureSize = 128);

// An index for `material` in `s` (appended).
int addMaterial(scene::Scene& s, scene::Material material);
// A mesh of one primitive with `material`, placed once at `world`.
void placeMesh(scene::Scene& s, scene::Primitive mesh, int material, const glm::mat4& world);

// A perspective camera at `eye` looking at `target`.
scene::Camera cameraAt(const glm::vec3& eye, const glm::vec3& target, float znear = 0.1f, float zfar = 100.0f,
                       float yfov = 0.8f);

// Translates everything (instances, lights, cameras) by `offset`, composed in
// double precision so the only rounding is the float result's.
void translateScene(scene::Scene& s, const glm::dvec3& offset);
scene::Camera translated(scene::Camera camera, const glm::dvec3& offset);
// Scales everything about the origin by `factor`; point and spot lights get
// factor^2 the intensity so the image stays the same.
void scaleScene(scene::Scene& s, float factor);
scene::Camera scaled(scene::Camera camera, float factor);

}  // namespace sg::test
