#include <shadelgraph/plugin/registry.hpp>

#include <algorithm>
#include <cctype>

namespace sg::plugin {
namespace {

bool validName(const std::string& name) {
  return !name.empty() && std::isalpha(static_cast<unsigned char>(name[0])) &&
         std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_'; });
}

std::string credit(const std::string& what, const std::string& name, const std::string& plugin) {
  return what + " '" + name + "' (plugin '" + plugin + "')";
}

// Registers `item` under its name in `table`, or throws naming both plugins.
template <class Item>
void addNamed(std::map<std::string, Item>& table, Item item, const char* what) {
  if (!validName(item.name))
    throw PluginError(credit(what, item.name, item.plugin) +
                      ": a name starts with a letter and has only letters, digits, '-' and '_'");
  if (auto it = table.find(item.name); it != table.end())
    throw PluginError(credit(what, item.name, item.plugin) + ": already registered by plugin '" + it->second.plugin +
                      "'");
  std::string name = item.name;
  table.emplace(std::move(name), std::move(item));
}

}  // namespace

std::string glslName(const std::string& layerName) {
  std::string name = layerName;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

void Registry::addLayer(MaterialLayer layer) {
  layer.plugin = plugin_;
  if (layer.source.empty() || layer.function.empty())
    throw PluginError(credit("material layer", layer.name, plugin_) + ": needs a GLSL source and a function name");
  addNamed(layers_, std::move(layer), "material layer");
}

void Registry::addMaterial(MaterialStack material) {
  material.plugin = plugin_;
  addNamed(materials_, std::move(material), "material");
}

void Registry::addPass(PassPlugin pass) {
  pass.plugin = plugin_;
  if (!pass.declare) throw PluginError(credit("pass", pass.name, plugin_) + ": has no declare function");
  for (const auto* list : {&pass.reads, &pass.writes})
    for (const auto& resource : *list)
      if (resource.empty()) throw PluginError(credit("pass", pass.name, plugin_) + ": a frame resource has no name");
  addNamed(passes_, std::move(pass), "pass");
}

void Registry::addFrame(FrameDescription frame) {
  if (!validName(frame.name))
    throw PluginError("frame '" + frame.name + "' (plugin '" + plugin_ +
                      "'): a name starts with a letter and has only letters, digits, '-' and '_'");
  if (frames_.count(frame.name)) throw PluginError("frame '" + frame.name + "' (plugin '" + plugin_ + "'): already registered");
  std::string name = frame.name;
  frames_.emplace(std::move(name), std::move(frame));
}

const PassPlugin& Registry::pass(const std::string& name) const {
  auto it = passes_.find(name);
  if (it == passes_.end()) throw PluginError("no pass '" + name + "' is registered (known: " + join(passNames()) + ")");
  return it->second;
}

std::vector<std::string> Registry::passNames() const {
  std::vector<std::string> names;
  for (const auto& [name, pass] : passes_) names.push_back(name);
  return names;
}

const FrameDescription& Registry::frame(const std::string& name) const {
  auto it = frames_.find(name);
  if (it == frames_.end()) throw PluginError("no frame '" + name + "' is registered (known: " + join(frameNames()) + ")");
  return it->second;
}

std::vector<std::string> Registry::frameNames() const {
  std::vector<std::string> names;
  for (const auto& [name, frame] : frames_) names.push_back(name);
  return names;
}

std::string join(const std::vector<std::string>& names) {
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : ", ") + n;
  return joined;
}

const MaterialLayer& Registry::layer(const std::string& name) const {
  auto it = layers_.find(name);
  if (it == layers_.end()) throw PluginError("no material layer '" + name + "' is registered");
  return it->second;
}

const MaterialStack& Registry::material(const std::string& name) const {
  auto it = materials_.find(name);
  if (it == materials_.end()) {
    std::string known;
    for (const auto& [n, m] : materials_) known += (known.empty() ? "" : ", ") + n;
    throw PluginError("no material '" + name + "' is registered (known: " + known + ")");
  }
  return it->second;
}

bool Registry::runsIn(const MaterialStack& material, ShadingPath path) const {
  const LayerPaths excluded = path == ShadingPath::Decoupled ? LayerPaths::ForwardOnly : LayerPaths::DecoupledOnly;
  return std::none_of(material.layers.begin(), material.layers.end(),
                      [&](const std::string& l) { return layer(l).paths == excluded; });
}

const MaterialStack& Registry::materialFor(const std::string& name, ShadingPath path) const {
  const MaterialStack& stack = material(name);
  if (path == ShadingPath::Forward && !runsIn(stack, path) && !stack.forwardFallback.empty())
    return material(stack.forwardFallback);
  return stack;
}

std::vector<std::string> Registry::materialNames() const {
  std::vector<std::string> names;
  for (const auto& [name, m] : materials_) names.push_back(name);
  return names;
}

std::vector<std::string> Registry::problems() const {
  std::vector<std::string> problems;
  for (const auto& [name, l] : layers_) {
    const std::string who = credit("material layer", name, l.plugin);
    for (const auto& read : l.reads) {
      if (read.radius > kMaxLayerRadius)
        problems.push_back(who + ": reads '" + read.layer + "' with radius " + std::to_string(read.radius) +
                           ", more than the " + std::to_string(kMaxLayerRadius) + " shadels supported");
      if (read.radius > 0 && l.paths != LayerPaths::DecoupledOnly)
        problems.push_back(who + ": reads a neighbourhood of '" + read.layer +
                           "', which only exists in shadel space: declare it DecoupledOnly");
      if (l.persistent && l.paths == LayerPaths::ForwardOnly)
        problems.push_back(who + ": is persistent, which only means something decoupled");
    }
    if (l.viewIndependent() && l.refreshShadeFrames == 0)
      problems.push_back(who + ": is view-independent with refreshShadeFrames 0; 1 or more (1: every shade frame)");
    if (l.viewIndependent() && l.persistent)
      problems.push_back(who + ": is both persistent and view-independent; a persistent layer decides its reuse itself");
    for (const auto& texture : l.textures) {
      if (!validName(texture.name) || texture.name.find('-') != std::string::npos)
        problems.push_back(who + ": texture name '" + texture.name + "' is not a GLSL identifier");
      if (!std::filesystem::is_regular_file(texture.file))
        problems.push_back(who + ": texture '" + texture.name + "': no such file " + texture.file.string());
    }
  }
  for (const auto& [name, m] : materials_) {
    const std::string who = credit("material", name, m.plugin);
    if (m.layers.empty()) problems.push_back(who + ": has no layers");
    bool known = true;
    for (size_t i = 0; i < m.layers.size(); ++i) {
      auto it = layers_.find(m.layers[i]);
      if (it == layers_.end()) {
        problems.push_back(who + ": layer '" + m.layers[i] + "' is not registered");
        known = false;
        continue;
      }
      for (const auto& read : it->second.reads) {
        const auto before = m.layers.begin() + std::ptrdiff_t(i);
        if (std::find(m.layers.begin(), before, read.layer) == before)
          problems.push_back(who + ": layer '" + m.layers[i] + "' reads '" + read.layer +
                             "', which does not come before it in the stack");
      }
    }
    if (!known || m.layers.empty()) continue;
    const MaterialLayer& last = layer(m.layers.back());
    if (last.format != graph::Format::RGBA16F)
      problems.push_back(who + ": its last layer '" + last.name + "' writes the shaded colour and must be RGBA16F");
    if (last.persistent)
      problems.push_back(who + ": its last layer '" + last.name +
                         "' is persistent; a persistent layer keeps its own image, so put a layer after it");
    if (last.viewIndependent())
      problems.push_back(who + ": its last layer '" + last.name +
                         "' is view-independent; a kept layer keeps its own image, so put a layer after it");
    uint32_t support = 0;  // each layer widens what the one after it reads
    for (const auto& l : m.layers) support += layer(l).radius();
    if (support > kMaxLayerRadius)
      problems.push_back(who + ": its layers' radii add up to " + std::to_string(support) + " shadels, more than the " +
                         std::to_string(kMaxLayerRadius) + " support-expand provides");
    if (!runsIn(m, ShadingPath::Forward)) {
      if (m.forwardFallback.empty())
        problems.push_back(who + ": has decoupled-only layers and names no forward fallback");
      else if (!hasMaterial(m.forwardFallback))
        problems.push_back(who + ": forward fallback '" + m.forwardFallback + "' is not registered");
      else if (!runsIn(material(m.forwardFallback), ShadingPath::Forward))
        problems.push_back(who + ": forward fallback '" + m.forwardFallback + "' cannot run forward either");
    }
  }
  return problems;
}

void Registry::check() const {
  const auto list = problems();
  if (list.empty()) return;
  std::string message = "the registered materials are inconsistent:";
  for (const auto& p : list) message += "\n  " + p;
  throw PluginError(message);
}

}  // namespace sg::plugin
