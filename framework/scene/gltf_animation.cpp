#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include <shadelgraph/scene/gltf_accessor.hpp>
#include <shadelgraph/scene/gltf_animation.hpp>

namespace sg::scene::detail {
namespace {

std::optional<AnimatedPath> parsePath(const std::string& path) {
  if (path == "translation") return AnimatedPath::Translation;
  if (path == "rotation") return AnimatedPath::Rotation;
  if (path == "scale") return AnimatedPath::Scale;
  if (path == "weights") return AnimatedPath::Weights;
  return std::nullopt;
}

class AnimationReader {
 public:
  AnimationReader(const GltfContext& context, const std::vector<int>& sceneNodeOf)
      : context_(context), model_(context.model), sceneNodeOf_(sceneNodeOf) {}

  Animation read(size_t index) {
    const tinygltf::Animation& in = model_.animations[index];
    const std::string name = describe("animation", index, in.name);
    Animation out;
    out.name = in.name.empty() ? "animation " + std::to_string(index) : in.name;
    for (size_t c = 0; c < in.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = in.channels[c];
      const std::string where = name + " channel " + std::to_string(c);
      const auto path = parsePath(channel.target_path);
      if (!path) {
        warn(where + ": target path '" + channel.target_path + "' is not supported; skipped");
        continue;
      }
      if (channel.target_node < 0) continue;  // glTF: no node, the channel is ignored (an extension may use it)
      const int node = sceneNodeOf_.at(static_cast<size_t>(channel.target_node));
      if (node < 0) continue;  // not in the scene shown
      if (model_.nodes[static_cast<size_t>(channel.target_node)].matrix.size() == 16 && *path != AnimatedPath::Weights) {
        warn(where + ": node " + std::to_string(channel.target_node) +
             " has a matrix, which glTF forbids animating; channel skipped");
        continue;
      }
      out.channels.push_back({node, *path, channel.sampler});
    }
    // What a kept channel drives with each sampler (the last one's path); unused samplers are only read.
    std::vector<std::optional<AnimatedPath>> use(in.samplers.size());
    for (const AnimationChannel& channel : out.channels) use[static_cast<size_t>(channel.sampler)] = channel.path;
    for (size_t s = 0; s < in.samplers.size(); ++s)
      out.samplers.push_back(sampler(in.samplers[s], name + " sampler " + std::to_string(s), use[s]));
    for (const AnimationChannel& channel : out.channels) {
      const AnimationSampler& s = out.samplers[static_cast<size_t>(channel.sampler)];
      const uint32_t width = channel.path == AnimatedPath::Rotation ? 4u : channel.path == AnimatedPath::Weights ? s.width : 3u;
      if (s.width != width)
        throw InvalidAsset(name + " sampler " + std::to_string(channel.sampler) + " drives both " +
                           std::to_string(s.width) + "- and " + std::to_string(width) + "-component properties");
    }
    return out;
  }

 private:
  void warn(const std::string& what) { context_.warnings.push_back(what); }

  // Accessors as floats, each read once however many samplers share it.
  const std::vector<float>& floats(int accessor, const std::string& what, PackedAccessor* shape) {
    auto it = cache_.find(accessor);
    if (it == cache_.end()) {
      PackedAccessor packed = readAccessor(model_, accessor, what);
      std::vector<float> values = toFloats(packed);
      packed.bytes.clear();
      it = cache_.emplace(accessor, Cached{std::move(packed), std::move(values)}).first;
    }
    *shape = it->second.shape;
    return it->second.values;
  }

  AnimationSampler sampler(const tinygltf::AnimationSampler& in, const std::string& where, std::optional<AnimatedPath> use) {
    AnimationSampler out;
    if (in.interpolation.empty() || in.interpolation == "LINEAR") out.interpolation = Interpolation::Linear;
    else if (in.interpolation == "STEP") out.interpolation = Interpolation::Step;
    else if (in.interpolation == "CUBICSPLINE") out.interpolation = Interpolation::CubicSpline;
    else throw InvalidAsset(where + ": interpolation '" + in.interpolation + "' is not LINEAR, STEP or CUBICSPLINE");

    PackedAccessor input, output;
    out.times = floats(in.input, where + " input", &input);
    if (input.components != 1 || input.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      throw InvalidAsset(where + ": input must be SCALAR FLOAT times, not " + typeName(input.components) + " " +
                         componentTypeName(input.componentType));
    if (out.times.empty()) throw InvalidAsset(where + ": input has no keyframes");
    for (size_t k = 0; k < out.times.size(); ++k) {
      if (!std::isfinite(out.times[k])) throw InvalidAsset(where + ": keyframe time " + std::to_string(k) + " is not finite");
      if (k > 0 && !(out.times[k] > out.times[k - 1]))
        throw InvalidAsset(where + ": keyframe times must increase strictly; time " + std::to_string(k) + " (" +
                           std::to_string(out.times[k]) + ") follows " + std::to_string(out.times[k - 1]));
    }

    out.values = floats(in.output, where + " output", &output);
    const bool rotation = use == AnimatedPath::Rotation;
    const bool weights = use == AnimatedPath::Weights;
    const int expectedComponents = !use ? output.components : weights ? 1 : rotation ? 4 : 3;
    if (output.components != expectedComponents)
      throw InvalidAsset(where + ": output is " + typeName(output.components) + ", its channel needs " +
                         typeName(expectedComponents));
    if (output.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !((!use || rotation || weights) && output.normalized))
      throw InvalidAsset(where + ": output must be FLOAT (or normalized integers for rotations and weights), not " +
                         std::string(componentTypeName(output.componentType)));
    const size_t groups = (out.interpolation == Interpolation::CubicSpline ? 3 : 1) * out.times.size();
    const size_t perKey = weights || !use ? output.count / groups : 1;  // weights: one per morph target
    if (perKey == 0 || output.count != groups * perKey)
      throw InvalidAsset(where + ": output has " + std::to_string(output.count) + " elements for " +
                         std::to_string(out.times.size()) + " keyframes" +
                         (out.interpolation == Interpolation::CubicSpline ? " (CUBICSPLINE: 3 per keyframe)" : ""));
    for (size_t v = 0; v < out.values.size(); ++v)
      if (!std::isfinite(out.values[v])) throw InvalidAsset(where + ": output value " + std::to_string(v) + " is not finite");
    out.width = static_cast<uint32_t>(perKey * static_cast<size_t>(output.components));
    return out;
  }

  struct Cached {
    PackedAccessor shape;  // without its bytes
    std::vector<float> values;
  };
  const GltfContext& context_;
  const tinygltf::Model& model_;
  const std::vector<int>& sceneNodeOf_;
  std::map<int, Cached> cache_;
};

}  // namespace

void convertAnimations(const GltfContext& context, const std::vector<int>& sceneNodeOf, Scene& scene) {
  AnimationReader reader(context, sceneNodeOf);
  for (size_t a = 0; a < context.model.animations.size(); ++a) scene.animations.push_back(reader.read(a));
}

}  // namespace sg::scene::detail
