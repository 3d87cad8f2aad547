#pragma once
#include <memory>
#include <optional>

#include <shadelgraph/plugin/registry.hpp>
#include <shadelgraph/render/renderer.hpp>

#include "decoupled_shading.hpp"

namespace sg::plugins {

// Frame state key of the DecoupledShading the decoupled passes share
// (render::Renderer::provideState).
inline constexpr const char* kDecoupledState = "decoupled";

// The decoupled-shading package: shadel-clear, shadel-mark, support-expand,
// shadel-allocate, work-aggregate, layer-shade, composite, counters-readback
// and the decoupled debug views, and the frame "decoupled" (the forward
// package's passes around them; objects in mode forward stay forward). Needs
// the forward package registered for its frame.
void registerDecoupledPackage(plugin::Registry& registry);

// A renderer of `scene` running `frame`, with the DecoupledShading its
// decoupled passes share. `mode`: every object's mode (else each its own).
// Objects in mode decoupled without a chart get an automatic one first, so
// `scene` may change; it must outlive the renderer.
struct DecoupledRenderer {
  std::shared_ptr<DecoupledShading> shading;
  std::unique_ptr<render::Renderer> renderer;
};
DecoupledRenderer makeDecoupledRenderer(gpu::Device& device, scene::Scene& scene, const plugin::Registry& registry,
                                        plugin::ResolvedFrame frame, std::optional<scene::ShadingMode> mode = {},
                                        DecoupledSettings settings = {});
// The same with a registered frame (default: "decoupled").
DecoupledRenderer makeDecoupledRenderer(gpu::Device& device, scene::Scene& scene, const plugin::Registry& registry,
                                        std::optional<scene::ShadingMode> mode = {}, DecoupledSettings settings = {},
                                        const std::string& frame = "decoupled");

}  // namespace sg::plugins
