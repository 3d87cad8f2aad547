#include "layer_plan.hpp"

#include <algorithm>

#include "decoupled_tables.hpp"

namespace sg::plugins {
namespace {

template <class T>
void addUnique(std::vector<T>& list, const T& value) {
  if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
}

}  // namespace

LayerPlan planLayers(const plugin::Registry& registry, std::span<const uint32_t> objects,
                     std::span<const std::string> objectMaterials) {
  LayerPlan plan;
  for (size_t i = 0; i < objects.size(); ++i) {
    const plugin::MaterialStack& material = registry.material(objectMaterials[i]);
    if (supportRadius(registry, material) > 0) plan.needsSupport = true;
    if (plan.depths.size() < material.layers.size()) plan.depths.resize(material.layers.size());
    for (size_t d = 0; d < material.layers.size(); ++d) {
      const std::string& name = material.layers[d];
      const bool final = d + 1 == material.layers.size();
      auto& steps = plan.depths[d];
      auto step = std::find_if(steps.begin(), steps.end(),
                               [&](const LayerStep& s) { return s.layer == name && s.final == final; });
      if (step == steps.end()) step = steps.insert(steps.end(), LayerStep{name, final, {}});
      step->objects.push_back(objects[i]);
      ++plan.dispatches;
      if (!final) addUnique(plan.images, name);
      if (registry.layer(name).keepsValues()) addUnique(plan.persistent, name);
    }
  }
  if (plan.persistent.size() > kMaxPersistentLayers)
    throw plugin::PluginError("the visible objects' materials have " + std::to_string(plan.persistent.size()) +
                              " persistent layers; at most " + std::to_string(kMaxPersistentLayers) + " are counted");
  return plan;
}

uint32_t supportRadius(const plugin::Registry& registry, const plugin::MaterialStack& material) {
  uint32_t radius = 0;
  for (const auto& name : material.layers) radius += registry.layer(name).radius();
  return radius;
}

}  // namespace sg::plugins
