#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <shadelgraph/scene/gltf_nodes.hpp>

namespace sg::scene::detail {
namespace {

std::string nodeName(const tinygltf::Model& model, int index) {
  return describe("node", static_cast<size_t>(index), model.nodes[static_cast<size_t>(index)].name);
}

// Checks children references and that the nodes form a forest (glTF: "the
// node hierarchy MUST be a set of disjoint strict trees"); returns each
// node's parent (-1 for roots). Iterative, so deep or cyclic files cannot
// overflow the stack.
std::vector<int> parents(const tinygltf::Model& model) {
  const int count = static_cast<int>(model.nodes.size());
  std::vector<int> parent(model.nodes.size(), -1);
  for (int n = 0; n < count; ++n) {
    for (int child : model.nodes[static_cast<size_t>(n)].children) {
      if (child < 0 || child >= count)
        throw InvalidAsset(nodeName(model, n) + ": child " + std::to_string(child) + " does not exist (the file has " +
                           std::to_string(count) + " nodes)");
      if (child == n) throw InvalidAsset("node hierarchy has a cycle: " + nodeName(model, n) + " is its own child");
      int& slot = parent[static_cast<size_t>(child)];
      if (slot >= 0)
        throw InvalidAsset(nodeName(model, child) + " has two parents, " + nodeName(model, slot) + " and " +
                           nodeName(model, n) + " (glTF nodes form strict trees)");
      slot = n;
    }
  }
  // With at most one parent each, a cycle is a parent chain that returns to itself.
  enum : char { Unvisited, OnChain, Done };
  std::vector<char> state(model.nodes.size(), Unvisited);
  for (int start = 0; start < count; ++start) {
    std::vector<int> chain;
    int n = start;
    while (n >= 0 && state[static_cast<size_t>(n)] == Unvisited) {
      state[static_cast<size_t>(n)] = OnChain;
      chain.push_back(n);
      n = parent[static_cast<size_t>(n)];
    }
    if (n >= 0 && state[static_cast<size_t>(n)] == OnChain) {
      // chain[k + 1] is chain[k]'s parent and chain.back()'s parent is n:
      // name the cycle parent first, n -> chain.back() -> ... -> n.
      // At most kShown nodes are named: a 50,000-node cycle would be a 700 KB line.
      constexpr size_t kShown = 8;
      const auto first = static_cast<size_t>(std::find(chain.begin(), chain.end(), n) - chain.begin());
      std::string text = nodeName(model, n);
      size_t shown = 1;
      for (size_t k = chain.size() - 1; k > first; --k, ++shown) {
        if (shown == kShown) {
          text += " -> ... (" + std::to_string(k - first) + " more)";
          break;
        }
        text += " -> " + nodeName(model, chain[k]);
      }
      throw InvalidAsset("node hierarchy has a cycle: " + text + " -> " + nodeName(model, n));
    }
    for (int c : chain) state[static_cast<size_t>(c)] = Done;
  }
  return parent;
}

glm::mat4 localTransform(const tinygltf::Node& node, const std::string& name) {
  glm::dmat4 local(1.0);
  if (node.matrix.size() == 16) {
    local = glm::make_mat4(node.matrix.data());  // column-major, as glTF stores it
  } else {
    glm::dvec3 translation(0.0), scale(1.0);
    glm::dquat rotation(1.0, 0.0, 0.0, 0.0);
    if (node.translation.size() == 3) translation = glm::make_vec3(node.translation.data());
    if (node.scale.size() == 3) scale = glm::make_vec3(node.scale.data());
    if (node.rotation.size() == 4) {
      // glTF stores x, y, z, w.
      rotation = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      if (glm::length(rotation) > 0.0) rotation = glm::normalize(rotation);
    }
    local = glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(rotation) * glm::scale(glm::dmat4(1.0), scale);
  }
  const glm::mat4 result(local);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(result[c][r])) throw InvalidAsset(name + ": transform is not finite");
  return result;
}

std::optional<ShadingMode> shadingFromExtras(const tinygltf::Node& node, const std::string& name,
                                             std::vector<std::string>& warnings) {
  if (!node.extras.IsObject() || !node.extras.Has("shading")) return std::nullopt;
  const tinygltf::Value& value = node.extras.Get("shading");
  if (value.IsString())
    if (const auto mode = parseShadingMode(value.Get<std::string>())) return mode;
  warnings.push_back(name + ": extras.shading must be \"auto\", \"decoupled\" or \"forward\"; ignored");
  return std::nullopt;
}

Camera toCamera(const tinygltf::Camera& in, const std::string& name) {
  Camera out;
  out.name = in.name;
  if (in.type == "orthographic") {
    const tinygltf::OrthographicCamera& o = in.orthographic;
    out.projection = Projection::Orthographic;
    out.xmag = static_cast<float>(o.xmag);
    out.ymag = static_cast<float>(o.ymag);
    out.znear = static_cast<float>(o.znear);
    out.zfar = static_cast<float>(o.zfar);
    if (o.xmag == 0.0 || o.ymag == 0.0 || o.znear < 0.0 || !(o.zfar > o.znear))
      throw InvalidAsset(name + ": orthographic camera needs xmag, ymag != 0 and 0 <= znear < zfar");
    if (!(out.zfar > out.znear)) throw InvalidAsset(name + ": orthographic zfar and znear are equal as 32-bit floats");
  } else {
    const tinygltf::PerspectiveCamera& p = in.perspective;
    out.projection = Projection::Perspective;
    out.yfov = static_cast<float>(p.yfov);
    out.znear = static_cast<float>(p.znear);
    if (p.aspectRatio > 0.0) out.aspectRatio = static_cast<float>(p.aspectRatio);
    if (p.zfar > 0.0) out.zfar = static_cast<float>(p.zfar);
    if (!(p.yfov > 0.0) || !(p.znear > 0.0) || (p.zfar > 0.0 && !(p.zfar > p.znear)) || p.aspectRatio < 0.0)
      throw InvalidAsset(name + ": perspective camera needs yfov > 0, znear > 0, zfar > znear, aspectRatio > 0");
    // tan(yfov / 2) turns negative at pi: the image would be upside down or empty.
    if (!(p.yfov < std::numbers::pi))
      throw InvalidAsset(name + ": perspective yfov " + std::to_string(p.yfov) + " must be below pi");
    if (out.zfar && !(*out.zfar > out.znear))
      throw InvalidAsset(name + ": perspective zfar and znear are equal as 32-bit floats");
  }
  // Finite inputs can still give a non-finite projection (zfar * znear overflows).
  const glm::mat4 projection = out.projectionMatrix(1.0f);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(projection[c][r]))
        throw InvalidAsset(name + ": its znear, zfar, yfov, xmag, ymag give a non-finite projection matrix");
  return out;
}

Light toLight(const tinygltf::Light& in, const std::string& name) {
  Light out;
  out.name = in.name;
  if (in.type == "directional") out.type = LightType::Directional;
  else if (in.type == "point") out.type = LightType::Point;
  else if (in.type == "spot") out.type = LightType::Spot;
  else throw InvalidAsset(name + ": unknown light type '" + in.type + "'");
  if (in.color.size() == 3)
    out.color = glm::vec3(static_cast<float>(in.color[0]), static_cast<float>(in.color[1]), static_cast<float>(in.color[2]));
  out.intensity = static_cast<float>(in.intensity);
  out.range = static_cast<float>(in.range);
  out.innerConeAngle = static_cast<float>(in.spot.innerConeAngle);
  out.outerConeAngle = static_cast<float>(in.spot.outerConeAngle);
  if (out.type == LightType::Spot &&
      !(out.innerConeAngle >= 0.0f && out.innerConeAngle < out.outerConeAngle &&
        out.outerConeAngle <= std::numbers::pi_v<float> / 2 + 1e-6f))
    throw InvalidAsset(name + ": spot cone angles need 0 <= innerConeAngle < outerConeAngle <= pi/2");
  if (in.extras.IsObject() && in.extras.Has("shadows")) {
    const tinygltf::Value& shadows = in.extras.Get("shadows");
    if (!shadows.IsBool()) throw InvalidAsset(name + ": extras.shadows must be true or false");
    out.shadows = shadows.Get<bool>();
  }
  return out;
}

class NodeWalker {
 public:
  NodeWalker(const GltfContext& context, Scene& scene) : context_(context), model_(context.model), scene_(scene) {}

  void walk(const std::vector<int>& roots) {
    struct Pending {
      int node;
      int parent;  // in Scene::nodes
      glm::mat4 parentWorld;
      ShadingMode shading;
    };
    std::vector<Pending> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, -1, glm::mat4(1.0f), ShadingMode::Auto});
    sceneNodeOf_.assign(model_.nodes.size(), -1);
    while (!stack.empty()) {
      const Pending pending = stack.back();
      stack.pop_back();
      const tinygltf::Node& node = model_.nodes[static_cast<size_t>(pending.node)];
      const std::string name = nodeName(model_, pending.node);
      const glm::mat4 world = pending.parentWorld * localTransform(node, name);
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          if (!std::isfinite(world[c][r]))
            throw InvalidAsset(name + ": world transform (its own times its parents') is not finite");
      const ShadingMode shading = shadingFromExtras(node, name, context_.warnings).value_or(pending.shading);
      const int sceneNode = keep(node, pending.node, pending.parent);
      place(node, pending.node, sceneNode, name, world, shading);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
        stack.push_back({*child, sceneNode, world, shading});
    }
  }

  // Scene::nodes index of each glTF node (-1: not in the scene shown).
  const std::vector<int>& sceneNodeOf() const { return sceneNodeOf_; }

 private:
  // The node's local transform kept in Scene::nodes (already checked finite by localTransform).
  int keep(const tinygltf::Node& in, int index, int parent) {
    Node out;
    out.name = in.name.empty() ? "node " + std::to_string(index) : in.name;
    out.parent = parent;
    if (in.matrix.size() == 16) {
      out.hasMatrix = true;
      out.matrix = glm::mat4(glm::make_mat4(in.matrix.data()));
    }
    if (in.translation.size() == 3) out.translation = glm::vec3(glm::make_vec3(in.translation.data()));
    if (in.scale.size() == 3) out.scale = glm::vec3(glm::make_vec3(in.scale.data()));
    if (in.rotation.size() == 4) {
      const glm::dquat q(in.rotation[3], in.rotation[0], in.rotation[1], in.rotation[2]);
      if (glm::length(q) > 0.0) out.rotation = glm::quat(glm::normalize(q));
    }
    out.weights = morphWeights(in, out.name);
    const auto sceneIndex = static_cast<int>(scene_.nodes.size());
    scene_.nodes.push_back(out);
    sceneNodeOf_[static_cast<size_t>(index)] = sceneIndex;
    return sceneIndex;
  }

  // The node's morph weights (glTF: they override its mesh's), one per target of its mesh.
  std::vector<float> morphWeights(const tinygltf::Node& in, const std::string& name) const {
    if (in.mesh < 0 || static_cast<size_t>(in.mesh) >= scene_.meshes.size()) return {};
    const std::vector<float>& defaults = scene_.meshes[static_cast<size_t>(in.mesh)].weights;
    if (in.weights.empty()) return defaults;
    if (in.weights.size() != defaults.size())
      throw InvalidAsset(name + ": " + std::to_string(in.weights.size()) + " weights for its mesh's " +
                         std::to_string(defaults.size()) + " morph targets");
    std::vector<float> out;
    for (double w : in.weights) {
      if (!std::isfinite(w)) throw InvalidAsset(name + ": a morph weight is not finite");
      out.push_back(static_cast<float>(w));
    }
    return out;
  }

  void place(const tinygltf::Node& node, int index, int sceneNode, const std::string& name, const glm::mat4& world,
             ShadingMode shading) {
    if (node.mesh >= 0) {
      if (static_cast<size_t>(node.mesh) >= model_.meshes.size())
        throw InvalidAsset(name + ": mesh " + std::to_string(node.mesh) + " does not exist (the file has " +
                           std::to_string(model_.meshes.size()) + ")");
      if (node.skin >= 0 && static_cast<size_t>(node.skin) >= model_.skins.size())
        throw InvalidAsset(name + ": skin " + std::to_string(node.skin) + " does not exist (the file has " +
                           std::to_string(model_.skins.size()) + ")");
      Instance instance;
      instance.mesh = node.mesh;
      instance.world = world;
      instance.name = node.name.empty() ? "node " + std::to_string(index) : node.name;
      instance.shading = shading;
      instance.node = sceneNode;
      instance.skin = node.skin;  // Scene::skins holds the file's skins in order (convertSkins)
      instance.morphWeights = scene_.nodes[static_cast<size_t>(sceneNode)].weights;
      scene_.instances.push_back(std::move(instance));
    }
    if (node.camera >= 0) {
      if (static_cast<size_t>(node.camera) >= model_.cameras.size())
        throw InvalidAsset(name + ": camera " + std::to_string(node.camera) + " does not exist (the file has " +
                           std::to_string(model_.cameras.size()) + ")");
      const tinygltf::Camera& in = model_.cameras[static_cast<size_t>(node.camera)];
      Camera camera = toCamera(in, describe("camera", static_cast<size_t>(node.camera), in.name));
      camera.world = world;
      camera.node = sceneNode;
      scene_.cameras.push_back(std::move(camera));
    }
    if (const auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end()) {
      const tinygltf::Value& extension = it->second;
      const int lightIndex =
          extension.IsObject() && extension.Get("light").IsInt() ? extension.Get("light").GetNumberAsInt() : -1;
      if (lightIndex < 0 || static_cast<size_t>(lightIndex) >= model_.lights.size())
        throw InvalidAsset(name + ": light " + std::to_string(lightIndex) + " does not exist (the file has " +
                           std::to_string(model_.lights.size()) + ")");
      const tinygltf::Light& in = model_.lights[static_cast<size_t>(lightIndex)];
      Light out = toLight(in, describe("light", static_cast<size_t>(lightIndex), in.name));
      out.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
      const glm::vec3 direction = glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f);
      if (glm::length(direction) > 0.0f) out.direction = glm::normalize(direction);
      scene_.lights.push_back(std::move(out));
    }
  }

  const GltfContext& context_;
  const tinygltf::Model& model_;
  Scene& scene_;
  std::vector<int> sceneNodeOf_;
};

}  // namespace

std::vector<int> convertNodes(const GltfContext& context, Scene& scene) {
  const tinygltf::Model& model = context.model;
  const std::vector<int> parent = parents(model);

  std::vector<int> roots;
  if (model.defaultScene >= 0 || !model.scenes.empty()) {
    const int sceneIndex = std::max(model.defaultScene, 0);
    if (static_cast<size_t>(sceneIndex) >= model.scenes.size())
      throw InvalidAsset("scene " + std::to_string(sceneIndex) + " does not exist (the file has " +
                         std::to_string(model.scenes.size()) + ")");
    roots = model.scenes[static_cast<size_t>(sceneIndex)].nodes;
    for (int root : roots) {
      if (root < 0 || static_cast<size_t>(root) >= model.nodes.size())
        throw InvalidAsset("scene " + std::to_string(sceneIndex) + ": node " + std::to_string(root) +
                           " does not exist (the file has " + std::to_string(model.nodes.size()) + ")");
      if (parent[static_cast<size_t>(root)] >= 0)
        throw InvalidAsset("scene " + std::to_string(sceneIndex) + " lists " + nodeName(model, root) +
                           " as a root, but it is a child of " + nodeName(model, parent[static_cast<size_t>(root)]));
    }
  } else {
    // No scene at all: glTF leaves this to the application; show every root.
    for (size_t n = 0; n < model.nodes.size(); ++n)
      if (parent[n] < 0) roots.push_back(static_cast<int>(n));
    if (!model.nodes.empty()) context.warnings.push_back("no scene; showing every root node");
  }
  if (roots.empty()) context.warnings.push_back("the scene has no nodes: nothing to draw");
  NodeWalker walker(context, scene);
  walker.walk(roots);
  return walker.sceneNodeOf();
}

}  // namespace sg::scene::detail
