#pragma once
// What plugins register and the renderer looks up: material layers, materials
// (layer stacks), GLSL source directories and post-processing passes. The
// built-ins (materials/builtin_materials.cpp) register here exactly like a
// plugin loaded with --plugin.
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <shadelgraph/graph/handles.hpp>
#include <shadelgraph/plugin/material_layer.hpp>
#include <shadelgraph/plugin/material_stack.hpp>

namespace sg::graph {
class RenderGraph;
}

namespace sg::plugin {

// A registration or lookup that cannot succeed; the message names the plugin.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class ShadingPath : uint8_t { Decoupled, Forward };

// A pass a plugin adds to every frame, on the HDR colour after shading and
// before exposure and tonemapping. It returns the colour's new version.
struct PostPass {
  std::string name;
  std::function<graph::ResourceHandle(graph::RenderGraph&, graph::ResourceHandle color)> declare;
  std::string plugin;
};

class Registry {
 public:
  // What is registered from now on is credited to `plugin` (in error messages).
  void beginPlugin(std::string plugin) { plugin_ = std::move(plugin); }
  const std::string& currentPlugin() const { return plugin_; }

  void addLayer(MaterialLayer layer);
  void addMaterial(MaterialStack material);
  // GLSL sources by virtual path (a layer's `source` and its #includes).
  void addShaderDirectory(std::filesystem::path directory) { shaderDirectories_.push_back(std::move(directory)); }
  void addPostPass(PostPass pass);

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
  const std::vector<PostPass>& postPasses() const { return postPasses_; }
  std::vector<std::string> materialNames() const;

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
  std::vector<PostPass> postPasses_;
};

// "blur-u" -> "blur_u": the layer's name as a GLSL identifier.
std::string glslName(const std::string& layerName);

}  // namespace sg::plugin
