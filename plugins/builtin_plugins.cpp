#include "builtin_plugins.hpp"

#include <builtin_materials.hpp>

#include "decoupled/decoupled_package.hpp"
#include "forward/forward_package.hpp"

namespace sg::plugins {

void registerBuiltins(plugin::Registry& registry) {
  materials::registerBuiltinMaterials(registry);
  registerForwardPackage(registry);
  registerDecoupledPackage(registry);
}

const plugin::Registry& builtinRegistry() {
  static const plugin::Registry registry = [] {
    plugin::Registry r;
    registerBuiltins(r);
    return r;
  }();
  return registry;
}

}  // namespace sg::plugins
