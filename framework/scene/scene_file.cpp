#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <shadelgraph/scene/input_limits.hpp>
#include <shadelgraph/scene/scene_file.hpp>

namespace sg::scene {
namespace {

using Json = nlohmann::json;
using detail::capText;
using detail::kFloatMax;
using detail::kMaxCoordinate;

// Errors inside the file: a JSON pointer and what is wrong with it.
class FormatError : public std::runtime_error {
 public:
  FormatError(const std::string& path, const std::string& what)
      : std::runtime_error((path.empty() ? "the document" : path) + ": " + what) {}
};

void allowOnly(const Json& object, const std::string& path, std::initializer_list<const char*> keys) {
  if (!object.is_object()) throw FormatError(path, "expected an object");
  const std::set<std::string> allowed(keys.begin(), keys.end());
  for (const auto& [key, value] : object.items())
    if (!allowed.contains(key)) throw FormatError(path, "unknown property '" + capText(key, 80) + "'");
}

// Numbers become 32-bit floats: 1e39 is finite as a double and infinite
// after. Coordinates (`limit` kMaxCoordinate) stay where squared lengths are finite.
float toFloat(const Json& value, const std::string& path, double limit) {
  if (!value.is_number()) throw FormatError(path, "expected a number");
  const double number = value.get<double>();
  if (!(std::abs(number) <= kFloatMax)) throw FormatError(path, value.dump() + " is outside the range of a 32-bit float");
  if (std::abs(number) > limit)
    throw FormatError(path, value.dump() + " is beyond +-1e18, where squared lengths overflow 32-bit float");
  return static_cast<float>(number);
}

float number(const Json& object, const char* key, const std::string& path, float fallback, double limit = kFloatMax) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  return toFloat(*it, path + "/" + key, limit);
}

float requiredNumber(const Json& object, const char* key, const std::string& path, double limit = kFloatMax) {
  if (!object.contains(key)) throw FormatError(path + "/" + key, "required property is missing");
  return number(object, key, path, 0.0f, limit);
}

template <int N>
glm::vec<N, float> vector(const Json& object, const char* key, const std::string& path, glm::vec<N, float> fallback,
                          double limit = kFloatMax) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  const std::string where = path + "/" + key;
  if (!it->is_array() || it->size() != N) throw FormatError(where, "expected an array of " + std::to_string(N) + " numbers");
  glm::vec<N, float> out;
  for (int i = 0; i < N; ++i) out[i] = toFloat((*it)[static_cast<size_t>(i)], where + "/" + std::to_string(i), limit);
  return out;
}

template <int N>
glm::vec<N, float> requiredVector(const Json& object, const char* key, const std::string& path, double limit = kFloatMax) {
  if (!object.contains(key)) throw FormatError(path + "/" + key, "required property is missing");
  return vector<N>(object, key, path, glm::vec<N, float>(0.0f), limit);
}

std::string text(const Json& object, const char* key, const std::string& path, const std::string& fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_string()) throw FormatError(path + "/" + key, "expected a string");
  return it->get<std::string>();
}

glm::vec3 direction(const Json& object, const std::string& path) {
  const glm::vec3 d = vector<3>(object, "direction", path, glm::vec3(0.0f, 0.0f, -1.0f), kMaxCoordinate);
  if (!(glm::length(d) > 0.0f)) throw FormatError(path + "/direction", "must not be zero (or is too long)");
  return glm::normalize(d);
}

glm::mat4 objectTransform(const Json& object, const std::string& path) {
  const glm::vec3 translation = vector<3>(object, "translation", path, glm::vec3(0.0f), kMaxCoordinate);
  glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
  if (object.contains("rotation") && object.contains("rotationDegrees"))
    throw FormatError(path, "give rotation or rotationDegrees, not both");
  if (object.contains("rotation")) {
    const glm::vec4 q = vector<4>(object, "rotation", path, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), kMaxCoordinate);
    if (!(glm::length(q) > 0.0f)) throw FormatError(path + "/rotation", "must not be zero (or is too long)");
    rotation = glm::normalize(glm::quat(q.w, q.x, q.y, q.z));
  } else if (object.contains("rotationDegrees")) {
    const glm::vec3 degrees = vector<3>(object, "rotationDegrees", path, glm::vec3(0.0f));
    const glm::vec3 radians = glm::radians(degrees);
    rotation = glm::angleAxis(radians.z, glm::vec3(0, 0, 1)) * glm::angleAxis(radians.y, glm::vec3(0, 1, 0)) *
               glm::angleAxis(radians.x, glm::vec3(1, 0, 0));
  }
  glm::vec3 scale(1.0f);
  if (const auto it = object.find("scale"); it != object.end())
    scale = it->is_number() ? glm::vec3(number(object, "scale", path, 1.0f, kMaxCoordinate))
                            : vector<3>(object, "scale", path, scale, kMaxCoordinate);
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

Light parseLight(const Json& json, const std::string& path) {
  allowOnly(json, path,
            {"type", "name", "color", "intensity", "range", "position", "direction", "innerConeAngle", "outerConeAngle",
             "shadows"});
  Light light;
  const std::string type = text(json, "type", path, "");
  if (type == "directional") light.type = LightType::Directional;
  else if (type == "point") light.type = LightType::Point;
  else if (type == "spot") light.type = LightType::Spot;
  else throw FormatError(path + "/type", "expected \"directional\", \"point\" or \"spot\"");
  light.name = text(json, "name", path, "");
  light.color = vector<3>(json, "color", path, glm::vec3(1.0f));
  light.intensity = number(json, "intensity", path, 1.0f);
  light.range = number(json, "range", path, 0.0f, kMaxCoordinate);
  light.position = vector<3>(json, "position", path, glm::vec3(0.0f), kMaxCoordinate);
  light.direction = direction(json, path);
  light.innerConeAngle = number(json, "innerConeAngle", path, 0.0f);
  light.outerConeAngle = number(json, "outerConeAngle", path, std::numbers::pi_v<float> / 4);
  if (light.type == LightType::Spot &&
      !(light.innerConeAngle >= 0.0f && light.innerConeAngle < light.outerConeAngle &&
        light.outerConeAngle <= std::numbers::pi_v<float> / 2 + 1e-6f))
    throw FormatError(path, "spot cone angles need 0 <= innerConeAngle < outerConeAngle <= pi/2");
  if (light.range < 0.0f) throw FormatError(path + "/range", "must be >= 0");
  if (const auto it = json.find("shadows"); it != json.end()) {
    if (!it->is_boolean()) throw FormatError(path + "/shadows", "expected true or false");
    light.shadows = it->get<bool>();
  }
  return light;
}

// A path's "keys": a non-empty array, each key parsed by `parse(key, keyPath)`, times increasing strictly.
template <class Key, class Parse>
std::vector<Key> keyList(const Json& json, const std::string& path, Parse parse) {
  const auto keys = json.find("keys");
  if (keys == json.end() || !keys->is_array() || keys->empty())
    throw FormatError(path + "/keys", "expected an array of at least one key");
  std::vector<Key> out;
  for (size_t k = 0; k < keys->size(); ++k) {
    const std::string keyPath = path + "/keys/" + std::to_string(k);
    Key parsed = parse((*keys)[k], keyPath);
    if (!out.empty() && !(parsed.time > out.back().time)) throw FormatError(keyPath + "/t", "key times must increase strictly");
    out.push_back(parsed);
  }
  return out;
}

CameraPath parseCameraPath(const Json& json, const std::string& path, size_t index) {
  if (!json.is_object()) throw FormatError(path, "expected an object");
  CameraPath out;
  const std::string type = text(json, "type", path, "");
  out.name = text(json, "name", path, "path " + std::to_string(index));
  if (type == "orbit") {
    allowOnly(json, path, {"type", "name", "center", "radius", "height", "seconds"});
    out.type = CameraPath::Type::Orbit;
    out.center = vector<3>(json, "center", path, glm::vec3(0.0f), kMaxCoordinate);
    out.radius = requiredNumber(json, "radius", path, kMaxCoordinate);
    out.height = number(json, "height", path, 0.0f, kMaxCoordinate);
    out.seconds = number(json, "seconds", path, 10.0f);
    if (!(out.radius > 0.0f)) throw FormatError(path + "/radius", "must be > 0");
    if (!(out.seconds > 0.0f)) throw FormatError(path + "/seconds", "must be > 0");
  } else if (type == "keys") {
    allowOnly(json, path, {"type", "name", "keys"});
    out.type = CameraPath::Type::Keys;
    out.keys = keyList<CameraKey>(json, path, [](const Json& key, const std::string& keyPath) {
      allowOnly(key, keyPath, {"t", "position", "target"});
      CameraKey parsed{requiredNumber(key, "t", keyPath), requiredVector<3>(key, "position", keyPath, kMaxCoordinate),
                       requiredVector<3>(key, "target", keyPath, kMaxCoordinate)};
      if (parsed.position == parsed.target) throw FormatError(keyPath, "position and target are the same point");
      return parsed;
    });
  } else {
    throw FormatError(path + "/type", "expected \"orbit\" or \"keys\"");
  }
  return out;
}

// An object's "path": rigid motion from its placed pose (object_motion.hpp).
ObjectMotion parseObjectPath(const Json& json, const std::string& path, const glm::vec3& pivot) {
  if (!json.is_object()) throw FormatError(path, "expected an object");
  ObjectMotion out;
  out.pivot = pivot;
  const std::string type = text(json, "type", path, "");
  out.spinDegreesPerSecond = number(json, "spinDegreesPerSecond", path, 0.0f, 1e6);
  if (type == "orbit") {
    allowOnly(json, path, {"type", "radius", "seconds", "spinDegreesPerSecond"});
    out.type = ObjectMotion::Type::Orbit;
    out.radius = requiredNumber(json, "radius", path, kMaxCoordinate);
    out.seconds = number(json, "seconds", path, 10.0f);
    if (!(out.radius > 0.0f)) throw FormatError(path + "/radius", "must be > 0");
    if (!(out.seconds > 0.0f)) throw FormatError(path + "/seconds", "must be > 0");
  } else if (type == "keys") {
    allowOnly(json, path, {"type", "keys", "spinDegreesPerSecond"});
    out.type = ObjectMotion::Type::Keys;
    out.keys = keyList<ObjectKey>(json, path, [](const Json& key, const std::string& keyPath) {
      allowOnly(key, keyPath, {"t", "translation"});
      return ObjectKey{requiredNumber(key, "t", keyPath), requiredVector<3>(key, "translation", keyPath, kMaxCoordinate)};
    });
  } else if (type == "spin") {
    allowOnly(json, path, {"type", "spinDegreesPerSecond"});
    if (!json.contains("spinDegreesPerSecond")) throw FormatError(path + "/spinDegreesPerSecond", "required property is missing");
  } else {
    throw FormatError(path + "/type", "expected \"orbit\", \"keys\" or \"spin\"");
  }
  return out;
}

std::string animationChoices(const std::vector<Animation>& animations) {
  std::string names;
  for (size_t a = 0; a < animations.size() && a < 20; ++a)
    names += (a ? ", " : "") + std::to_string(a) + " '" + capText(animations[a].name, 80) + "'";
  return "expected \"all\", \"none\", an index or a name; " +
         (names.empty() ? std::string("the glTF file has no animations") : "the glTF file's animations are " + names);
}

// The object's "animation" ("all" by default, "none", an index or a name) out
// of its glTF file's, each starting "timeOffset" seconds into its clock.
std::vector<Animation> chosenAnimations(const Json& object, const std::string& path,
                                        const std::vector<Animation>& animations) {
  const float offset = number(object, "timeOffset", path, 0.0f);
  std::vector<Animation> chosen;
  const auto it = object.find("animation");
  if (it == object.end() || (it->is_string() && it->get<std::string>() == "all")) {
    chosen = animations;
  } else if (it->is_number_unsigned() && it->get<uint64_t>() < animations.size()) {
    chosen = {animations[it->get<size_t>()]};
  } else if (it->is_string() && it->get<std::string>() != "none") {
    for (const Animation& animation : animations)
      if (animation.name == it->get<std::string>()) chosen = {animation};
    if (chosen.empty()) throw FormatError(path + "/animation", animationChoices(animations));
  } else if (!it->is_string()) {
    throw FormatError(path + "/animation", animationChoices(animations));
  }
  for (Animation& animation : chosen) animation.timeOffset = offset;
  return chosen;
}

SceneFile parse(const Json& root, const std::filesystem::path& file, const LoadOptions& options) {
  allowOnly(root, "", {"objects", "lights", "cameraPaths", "environment"});
  const auto objects = root.find("objects");
  if (objects == root.end() || !objects->is_array()) throw FormatError("/objects", "expected an array");

  SceneFile result;
  // Each glTF file is loaded once and its meshes, materials and textures are
  // stored once, however many objects place it.
  struct Placements {
    std::vector<Instance> instances;
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<Node> nodes;  // each object gets its own copy, so each animates on its own
    std::vector<Animation> animations;
    std::vector<Skin> skins;  // their joints are nodes: one copy per object too
    int meshBase = 0;
  };
  std::map<std::filesystem::path, Placements> loaded;
  for (size_t i = 0; i < objects->size(); ++i) {
    const std::string path = "/objects/" + std::to_string(i);
    const Json& object = (*objects)[i];
    allowOnly(object, path, {"gltf", "name", "translation", "rotation", "rotationDegrees", "scale", "shading",
                               "material", "path", "animation", "timeOffset"});
    const std::string gltf = text(object, "gltf", path, "");
    if (gltf.empty()) throw FormatError(path + "/gltf", "required property is missing");
    const std::filesystem::path gltfPath = (file.parent_path() / gltf).lexically_normal();
    std::optional<ShadingMode> shading;
    if (object.contains("shading")) {
      shading = parseShadingMode(text(object, "shading", path, ""));
      if (!shading) throw FormatError(path + "/shading", "expected \"auto\", \"decoupled\" or \"forward\"");
    }
    // Checked against the registered materials when the renderer starts (plugins may add them).
    const std::string material = text(object, "material", path, "");
    const glm::mat4 transform = objectTransform(object, path);
    const std::string name = text(object, "name", path, gltfPath.stem().string());
    const ObjectMotion motion =
        object.contains("path") ? parseObjectPath(object["path"], path + "/path", glm::vec3(transform[3])) : ObjectMotion{};

    auto it = loaded.find(gltfPath);
    if (it == loaded.end()) {
      Scene scene;
      try {
        scene = loadGltf(gltfPath, options);
      } catch (const SceneError& error) {
        throw FormatError(path + "/gltf", error.what());
      }
      // One load; its nodes and animations are placed once per object below.
      Placements placements{std::move(scene.instances), std::move(scene.lights),     std::move(scene.cameras),
                            std::move(scene.nodes),     std::move(scene.animations), std::move(scene.skins),
                            static_cast<int>(result.scene.meshes.size())};
      scene.instances.clear();
      scene.lights.clear();
      scene.cameras.clear();
      scene.nodes.clear();
      scene.animations.clear();
      scene.skins.clear();
      appendScene(result.scene, std::move(scene), glm::mat4(1.0f), gltfPath.filename().string() + ": ");
      it = loaded.emplace(gltfPath, std::move(placements)).first;
    }
    const Placements& placements = it->second;
    const int nodeBase = static_cast<int>(result.scene.nodes.size());
    for (Node node : placements.nodes) {
      if (node.parent < 0) node.placement = transform * node.placement;
      else node.parent += nodeBase;
      result.scene.nodes.push_back(std::move(node));
    }
    for (Animation animation : chosenAnimations(object, path, placements.animations)) {
      for (AnimationChannel& channel : animation.channels) channel.node += nodeBase;
      animation.name = name + "/" + animation.name;
      result.scene.animations.push_back(std::move(animation));
    }
    const int skinBase = static_cast<int>(result.scene.skins.size());
    for (Skin skin : placements.skins) {
      for (int& joint : skin.joints) joint += nodeBase;
      result.scene.skins.push_back(std::move(skin));
    }
    for (Instance instance : placements.instances) {
      instance.mesh += placements.meshBase;
      if (instance.node >= 0) instance.node += nodeBase;
      if (instance.skin >= 0) instance.skin += skinBase;
      instance.world = transform * instance.world;
      instance.name = name + "/" + instance.name;
      if (shading) instance.shading = *shading;
      if (!material.empty()) instance.material = material;
      instance.motion = motion;  // the whole object moves rigidly, every node with it
      result.scene.instances.push_back(std::move(instance));
    }
    Scene placed;  // lights and cameras, moved by appendScene's transform rules
    placed.lights = placements.lights;
    placed.cameras = placements.cameras;
    for (Camera& camera : placed.cameras)
      if (camera.node >= 0) camera.node += nodeBase;
    appendScene(result.scene, std::move(placed), transform);
  }

  if (const auto lights = root.find("lights"); lights != root.end()) {
    if (!lights->is_array()) throw FormatError("/lights", "expected an array");
    for (size_t i = 0; i < lights->size(); ++i)
      result.scene.lights.push_back(parseLight((*lights)[i], "/lights/" + std::to_string(i)));
  }
  if (const auto env = root.find("environment"); env != root.end()) {
    allowOnly(*env, "/environment", {"image", "intensity"});
    const std::string image = text(*env, "image", "/environment", "");
    if (image.empty()) throw FormatError("/environment/image", "required property is missing");
    const float intensity = number(*env, "intensity", "/environment", 1.0f);
    if (!(intensity >= 0.0f)) throw FormatError("/environment/intensity", "must be >= 0");
    try {
      result.scene.environment = loadEnvironment((file.parent_path() / image).lexically_normal(), intensity);
    } catch (const SceneError& error) {
      throw FormatError("/environment/image", error.what());
    }
  }
  if (const auto paths = root.find("cameraPaths"); paths != root.end()) {
    if (!paths->is_array()) throw FormatError("/cameraPaths", "expected an array");
    for (size_t i = 0; i < paths->size(); ++i)
      result.cameraPaths.push_back(parseCameraPath((*paths)[i], "/cameraPaths/" + std::to_string(i), i));
  }
  return result;
}

}  // namespace

SceneFile loadSceneFile(const std::filesystem::path& file, const LoadOptions& options) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw SceneError(file, "cannot open the file");
  const std::string text((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  if (stream.bad()) throw SceneError(file, "cannot read the file");
  // Bounded before the recursive parser sees it: deep nesting would overflow the stack.
  if (const auto error = detail::jsonDepthError(text)) throw SceneError(file, *error);
  try {
    const Json root = Json::parse(text);
    SceneFile result = parse(root, file, options);
    detail::capWarnings(result.scene.warnings);
    return result;
  } catch (const Json::parse_error& error) {
    throw SceneError(file, "invalid JSON: " + capText(error.what()));
  } catch (const Json::exception& error) {  // e.g. out_of_range for 1e999
    throw SceneError(file, "invalid JSON: " + capText(error.what()));
  } catch (const FormatError& error) {
    throw SceneError(file, capText(error.what(), 1000));
  } catch (const std::bad_alloc&) {
    throw SceneError(file, "out of memory");
  }
}

}  // namespace sg::scene
