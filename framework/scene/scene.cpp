#include <shadelgraph/scene/scene.hpp>

namespace sg::scene {

Bounds worldBounds(const Scene& scene) {
  Bounds bounds;
  for (const Instance& instance : scene.instances)
    bounds.extend(transformBounds(scene.meshes[static_cast<size_t>(instance.mesh)].bounds, instance.world));
  return bounds;
}

namespace {
// Whether a texture `material` samples (a present slot naming one of the
// scene's textures; material out of range: none) satisfies `test`.
template <class Test>
bool anySampledTexture(const Scene& scene, int material, Test test) {
  if (material < 0 || static_cast<size_t>(material) >= scene.materials.size()) return false;
  for (const TextureRef& ref : scene.materials[static_cast<size_t>(material)].textureSlots())
    if (ref.present() && static_cast<size_t>(ref.texture) < scene.textures.size() &&
        test(scene.textures[static_cast<size_t>(ref.texture)]))
      return true;
  return false;
}
}  // namespace

bool samplesUnmipmappedTexture(const Scene& scene, int material) {
  return anySampledTexture(scene, material, [&](const Texture& texture) {
    const auto sampler = static_cast<size_t>(texture.sampler);
    return sampler < scene.samplers.size() && scene.samplers[sampler].mipmapMode == MipmapMode::None;
  });
}

bool samplesTexture(const Scene& scene, int material) {
  return anySampledTexture(scene, material, [](const Texture&) { return true; });
}

size_t instancedTriangleCount(const Scene& scene) {
  size_t count = 0;
  for (const Instance& instance : scene.instances)
    count += scene.meshes[static_cast<size_t>(instance.mesh)].triangleCount();
  return count;
}

namespace {

int rebase(int index, size_t base) { return index < 0 ? index : index + static_cast<int>(base); }

void rebase(TextureRef& ref, size_t textureBase) { ref.texture = rebase(ref.texture, textureBase); }

}  // namespace

void appendScene(Scene& into, Scene other, const glm::mat4& transform, const std::string& warningPrefix) {
  const size_t meshBase = into.meshes.size();
  const size_t materialBase = into.materials.size();
  const size_t textureBase = into.textures.size();
  const size_t samplerBase = into.samplers.size();
  const size_t nodeBase = into.nodes.size();

  for (Mesh& mesh : other.meshes) {
    for (Primitive& primitive : mesh.primitives) primitive.material = rebase(primitive.material, materialBase);
    into.meshes.push_back(std::move(mesh));
  }
  for (Material& material : other.materials) {
    material.forEachTexture([&](TextureRef& ref) { rebase(ref, textureBase); });
    into.materials.push_back(std::move(material));
  }
  for (Texture& texture : other.textures) {
    texture.sampler = rebase(texture.sampler, samplerBase);
    into.textures.push_back(std::move(texture));
  }
  into.samplers.insert(into.samplers.end(), other.samplers.begin(), other.samplers.end());

  for (Node& node : other.nodes) {
    if (node.parent < 0) node.placement = transform * node.placement;
    node.parent = rebase(node.parent, nodeBase);
    into.nodes.push_back(node);
  }
  for (Animation& animation : other.animations) {
    for (AnimationChannel& channel : animation.channels) channel.node = rebase(channel.node, nodeBase);
    into.animations.push_back(std::move(animation));
  }
  const size_t skinBase = into.skins.size();
  for (Skin& skin : other.skins) {
    for (int& joint : skin.joints) joint = rebase(joint, nodeBase);
    into.skins.push_back(std::move(skin));
  }
  for (Instance& instance : other.instances) {
    instance.mesh = rebase(instance.mesh, meshBase);
    instance.skin = rebase(instance.skin, skinBase);
    instance.node = rebase(instance.node, nodeBase);
    instance.world = transform * instance.world;
    into.instances.push_back(std::move(instance));
  }
  for (Light& light : other.lights) {
    light.position = glm::vec3(transform * glm::vec4(light.position, 1.0f));
    const glm::vec3 direction = glm::mat3(transform) * light.direction;
    if (glm::length(direction) > 0.0f) light.direction = glm::normalize(direction);
    into.lights.push_back(std::move(light));
  }
  for (Camera& camera : other.cameras) {
    camera.world = transform * camera.world;
    camera.node = rebase(camera.node, nodeBase);
    into.cameras.push_back(std::move(camera));
  }
  for (std::string& warning : other.warnings) into.warnings.push_back(warningPrefix + warning);
  if (!into.environment.present()) into.environment = std::move(other.environment);
}

}  // namespace sg::scene
