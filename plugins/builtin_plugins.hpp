#pragma once
// Everything built in, registered like any plugin: the material layers and
// materials, the forward package and the decoupled-shading package.
#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugins {

void registerBuiltins(plugin::Registry& registry);

// A registry holding only the built-ins (for tools and tests without plugins).
const plugin::Registry& builtinRegistry();

}  // namespace sg::plugins
