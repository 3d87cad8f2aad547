#pragma once
// Drawing objects with the forward (fragment) variant of their material,
// generated from its layers (material_variant.hpp): shared by
// forward-opaque, alpha-mask and alpha-blend.
#include <span>
#include <string>
#include <vector>

#include <shadelgraph/gpu/pass_context.hpp>
#include <shadelgraph/graph/pass.hpp>
#include <shadelgraph/render/scene_view.hpp>

#include "z-prepass/overdraw_probe.hpp"

namespace sg::passes {

// The material a draw runs forward: its own, or that one's forward fallback.
const plugin::MaterialStack& forwardMaterial(const render::SceneView& view, uint32_t draw);
// The view's draws with this alpha mode, grouped by forward material (fewer pipeline switches).
std::vector<uint32_t> drawsWithAlphaMode(const render::SceneView& view, scene::AlphaMode mode);
// Draws `draws` in order, each with its material's pipeline (bound when it
// changes) and descriptor set. Opaque and masked draws write depth; blended
// ones test it and blend "over".
// Counts the samples of the draws with `counter` (a measurement frame's forward-opaque).
void drawForward(PassContext& ctx, const render::SceneView& view, std::span<const uint32_t> draws, bool blend,
                 OverdrawCounter counter = {});
// Declares that `pass` samples the frame resources the forward variants of
// these draws' materials read (MaterialLayer::frameInputs).
void readFrameInputs(graph::Pass& pass, const render::SceneView& view, std::span<const uint32_t> draws);
// Its pipeline, set 0 and push constants; the pass adds set 1 (the scene
// material) and set 2 (the layers' textures) when it has them. `plain`: the
// variant for draws with DrawItem::plainSurface (position and normal varyings);
// `frame`: what the frame provides; code for what it lacks is compiled out;
// `alphaTest`: the variant of alpha-mask draws (the others never discard).
struct ForwardFrameFeatures {
  bool shadowMaps = true;       // else SG_NO_SHADOW_MAPS: every light unshadowed
  bool lightGrid = true;        // else SG_NO_LIGHT_GRID: every light reaches every pixel
  bool environmentMaps = true;  // else SG_NO_ENVIRONMENT_MAPS: the analytic sky
  std::string key() const;      // part of the pipeline's name
};
gpu::GraphicsPipelineDesc forwardMaterialPipeline(const plugin::Registry& registry, const plugin::MaterialStack& material,
                                                  bool blend, bool plain = false, ForwardFrameFeatures frame = {},
                                                  bool alphaTest = true);
// Does the view hold a draw with this alpha mode?
bool hasAlphaMode(const render::SceneView& view, scene::AlphaMode mode);

}  // namespace sg::passes
