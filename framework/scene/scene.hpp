#pragma once
// A loaded scene: plain CPU data that the gpu and pass layers upload.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <shadelgraph/scene/animation.hpp>
#include <shadelgraph/scene/bounds.hpp>
#include <shadelgraph/scene/camera.hpp>
#include <shadelgraph/scene/environment.hpp>
#include <shadelgraph/scene/instance.hpp>
#include <shadelgraph/scene/light.hpp>
#include <shadelgraph/scene/material.hpp>
#include <shadelgraph/scene/mesh.hpp>
#include <shadelgraph/scene/node.hpp>
#include <shadelgraph/scene/skin.hpp>
#include <shadelgraph/scene/texture.hpp>

namespace sg::scene {

// Every index stored in one of these vectors (Instance::mesh, Instance::node,
// Camera::node, Node::parent, Instance::skin, Skin::joints, AnimationChannel::node, Primitive::material,
// TextureRef::texture, Texture::sampler) is valid.
struct Scene {
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Sampler> samplers;
  std::vector<Instance> instances;
  std::vector<Light> lights;
  std::vector<Camera> cameras;
  std::vector<Node> nodes;            // of glTF files, parents first
  std::vector<Animation> animations;  // of glTF files
  std::vector<Skin> skins;            // of glTF files
  std::vector<std::string> warnings;  // things skipped or repaired, one line each
  Environment environment;            // the environment light; none: the analytic sky
};

// World-space box around every instance.
Bounds worldBounds(const Scene& scene);
// Triangles drawn: instanced meshes counted once per instance.
size_t instancedTriangleCount(const Scene& scene);

// Whether `material` (an index into scene.materials; out of range: false)
// samples a texture whose sampler has no mip levels (glTF minFilter NEAREST or
// LINEAR): minified, it is sampled unfiltered.
bool samplesUnmipmappedTexture(const Scene& scene, int material);

// Whether `material` (an index into scene.materials; out of range: false)
// samples any texture.
bool samplesTexture(const Scene& scene, int material);

// Appends `other` to `into`, re-basing its indices, placing its instances,
// lights, cameras and root nodes under `transform`, and prefixing its warnings.
void appendScene(Scene& into, Scene other, const glm::mat4& transform, const std::string& warningPrefix = {});

}  // namespace sg::scene
