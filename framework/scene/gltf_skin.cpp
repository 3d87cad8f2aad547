#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include <shadelgraph/scene/gltf_accessor.hpp>
#include <shadelgraph/scene/gltf_skin.hpp>

namespace sg::scene::detail {
namespace {

Skin convertSkin(const tinygltf::Model& model, size_t index, const std::vector<int>& sceneNodeOf) {
  const tinygltf::Skin& in = model.skins[index];
  const std::string name = describe("skin", index, in.name);
  Skin out;
  out.name = in.name;
  for (const int joint : in.joints) {
    if (joint < 0 || static_cast<size_t>(joint) >= model.nodes.size())
      throw InvalidAsset(name + ": joint node " + std::to_string(joint) + " does not exist (the file has " +
                         std::to_string(model.nodes.size()) + ")");
    const int sceneNode = sceneNodeOf[static_cast<size_t>(joint)];
    if (sceneNode < 0) throw InvalidAsset(name + ": joint node " + std::to_string(joint) + " is not in the scene shown");
    out.joints.push_back(sceneNode);
  }
  out.inverseBindMatrices.assign(out.joints.size(), glm::mat4(1.0f));
  if (in.inverseBindMatrices >= 0) {
    const PackedAccessor accessor = readAccessor(model, in.inverseBindMatrices, name + " inverseBindMatrices");
    if (accessor.components != 16 || accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      throw InvalidAsset(name + ": inverseBindMatrices must be MAT4 of FLOAT, not " + typeName(accessor.components) +
                         " of " + componentTypeName(accessor.componentType));
    if (accessor.count < out.joints.size())
      throw InvalidAsset(name + ": " + std::to_string(accessor.count) + " inverseBindMatrices for " +
                         std::to_string(out.joints.size()) + " joints");
    const std::vector<float> floats = toFloats(accessor);
    for (size_t j = 0; j < out.joints.size(); ++j) {
      for (size_t k = 0; k < 16; ++k)
        if (!std::isfinite(floats[16 * j + k]))
          throw InvalidAsset(name + ": inverse bind matrix " + std::to_string(j) + " is not finite");
      out.inverseBindMatrices[j] = glm::make_mat4(floats.data() + 16 * j);  // column-major, as glTF stores it
    }
  }
  return out;
}

// The highest joint index a vertex gives weight to (zero-weight slots may hold anything).
uint32_t maxJoint(const Mesh& mesh) {
  uint32_t highest = 0;
  for (const Primitive& p : mesh.primitives)
    for (size_t v = 0; v < p.joints0.size(); ++v)
      for (int i = 0; i < 4; ++i) {
        if (p.weights0[v][i] > 0.0f) highest = std::max(highest, p.joints0[v][i]);
        if (!p.joints1.empty() && p.weights1[v][i] > 0.0f) highest = std::max(highest, p.joints1[v][i]);
      }
  return highest;
}

}  // namespace

void convertSkins(const GltfContext& context, const std::vector<int>& sceneNodeOf, Scene& scene) {
  for (size_t s = 0; s < context.model.skins.size(); ++s) scene.skins.push_back(convertSkin(context.model, s, sceneNodeOf));
  for (Instance& instance : scene.instances) {
    if (instance.skin < 0) continue;
    const Mesh& mesh = scene.meshes[static_cast<size_t>(instance.mesh)];
    const Skin& skin = scene.skins[static_cast<size_t>(instance.skin)];
    bool skinned = false;
    for (const Primitive& p : mesh.primitives) skinned |= p.skinned();
    if (!skinned) {
      context.warnings.push_back("object '" + instance.name + "' has a skin but its mesh has no JOINTS_0; not skinned");
      instance.skin = -1;
    } else if (maxJoint(mesh) >= skin.joints.size()) {
      throw InvalidAsset("object '" + instance.name + "': its mesh's JOINTS name joint " + std::to_string(maxJoint(mesh)) +
                         ", its skin has " + std::to_string(skin.joints.size()));
    }
  }
}

}  // namespace sg::scene::detail
