#pragma once
#include <shadelgraph/plugin/registry.hpp>

namespace sg::plugins {

// The forward package: the passes every frame shares (z-prepass,
// forward-opaque, alpha-mask, alpha-blend, exposure, tonemap) and the frame
// "forward" that shades every object with them.
void registerForwardPackage(plugin::Registry& registry);

}  // namespace sg::plugins
