#pragma once
// The built-in material layers and materials, registered like any plugin's.
#include <shadelgraph/plugin/registry.hpp>

namespace sg::materials {

void registerBuiltinMaterials(plugin::Registry& registry);

// A registry holding only the built-ins (for tools and tests without plugins).
const plugin::Registry& builtinMaterials();

}  // namespace sg::materials
