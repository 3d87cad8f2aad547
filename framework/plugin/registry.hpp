#pragma once
// What plugins register and the renderer looks up: material layers, materials
// (layer stacks), GLSL source directories, passes and frame descriptions. The
// built-ins (materials/, plugins/forward, plugins/decoupled) register here
// exactly like a plugin loaded with --plugin.
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <shadelgraph/plugin/frame_description.hpp>
#include <shadelgraph/plugin/material_layer.hpp>
#include <shadelgraph/plugin/material_stack.hpp>
#include <shadelgraph/plugin/pass_plugin.hpp>

namespace sg::plugin {

// A registration or lookup that cannot succeed; the message names the plugin.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ShadingPath : uint8_t { Decoupled, Forward };

class Registry {
 public:
  // What is registered from now on is credited to `plugin` (in error messages).
  void beginPlugin(std::string plugin) { plugin_ = std::move(plugin); }
  const std::string& currentPlugin() const { return plugin_; }

  void addLayer(MaterialLayer layer);
  void addMaterial(MaterialStack material);
  // GLSL sources by virtual path (a layer's `source` and its #includes).
  void addShaderDirectory(std::filesystem::path directory) { shaderDirectories_.push_back(std::move(directory)); }
  void addPass(PassPlugin pass);
  // A frame description (its passes need not be registered yet: frames are
  // checked when resolved).
  void addFrame(FrameDescription frame);

  bool hasLayer(const std::string& name) const { return layers_.count(name) != 0; }
  bool hasMaterial(const std::string& name) const { return materials_.count(name) != 0; }
  const MaterialLayer& layer(const std::string& name) const;
  const MaterialStack& material(const std::string& name) const;
  // The material an object of `name` runs in `path`: itself, or its forward
  // fallback when it has decoupled-only layers.
  const MaterialStack& materialFor(const std::string& name, ShadingPath path) const;
  // Can every layer of the material run in `path`?
  bool runsIn(const MaterialStack& material, ShadingPath path) const;

  const std::vector<std::filesystem::path>& shaderDirectories() const { return shaderDirectories_; }
  std::vector<std::string> materialNames() const;

  bool hasPass(const std::string& name) const { return passes_.count(name) != 0; }
  const PassPlugin& pass(const std::string& name) const;
  const std::map<std::string, PassPlugin>& passes() const { return passes_; }
  std::vector<std::string> passNames() const;
  bool hasFrame(const std::string& name) const { return frames_.count(name) != 0; }
  const FrameDescription& frame(const std::string& name) const;
  std::vector<std::string> frameNames() const;

  // Every inconsistency among what is registered: unknown layers in a stack,
  // a read of a layer that does not come earlier, a neighbourhood read in a
  // layer that claims to run forward, a missing forward fallback... Empty when
  // all is well; each message names the plugin.
  std::vector<std::string> problems() const;
  // Throws PluginError with every problem.
  void check() const;

 private:
  std::string plugin_ = "built-in";
  std::map<std::string, MaterialLayer> layers_;
  std::map<std::string, MaterialStack> materials_;
  std::vector<std::filesystem::path> shaderDirectories_;
  std::map<std::string, PassPlugin> passes_;
  std::map<std::string, FrameDescription> frames_;
};

// "blur-u" -> "blur_u": the layer's name as a GLSL identifier.
std::string glslName(const std::string& layerName);
// "a, b, c"
std::string join(const std::vector<std::string>& names);

}  // namespace sg::plugin
