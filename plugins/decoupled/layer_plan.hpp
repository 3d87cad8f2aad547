#pragma once
// Which layer dispatches a frame's decoupled objects need, as plain data: one
// layer-shade pass per stack depth, in each a step per layer (all objects
// whose material has that layer there), the intermediate layer images, and
// the persistent layers. Only the visible objects' materials contribute, so a
// frame holds exactly the layers its scene calls for.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugins {

struct LayerStep {
  std::string layer;
  bool final = false;             // writes the shaded colour composite reads, not the layer's own image
  std::vector<uint32_t> objects;  // decoupled object indices, one dispatch each
};

struct LayerPlan {
  std::vector<std::vector<LayerStep>> depths;  // depths[d]: the steps of the d-th layer-shade pass
  std::vector<std::string> images;             // layers whose own image some step writes (intermediate)
  std::vector<std::string> persistent;         // persistent and view-independent layers in use; index = counter slot
  uint32_t dispatches = 0;                     // sum over objects of their stack's size
  bool needsSupport = false;                   // some object's stack reads a neighbourhood
};

// objectMaterials[i]: the (decoupled) material of objects[i].
LayerPlan planLayers(const plugin::Registry& registry, std::span<const uint32_t> objects,
                     std::span<const std::string> objectMaterials);

// Shadels a material's last layer needs around the visible ones: the sum of
// its layers' radii (each layer widens what the one after it reads).
uint32_t supportRadius(const plugin::Registry& registry, const plugin::MaterialStack& material);

}  // namespace sg::plugins
