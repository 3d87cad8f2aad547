#include "forward_recipe.hpp"

#include "exposure/exposure.hpp"
#include "alpha-blend/alpha_blend.hpp"
#include "alpha-mask/alpha_mask.hpp"
#include "forward/forward.hpp"
#include "forward/forward_material.hpp"
#include "tonemap/tonemap.hpp"
#include "z-prepass/z_prepass.hpp"

namespace sg::plugins {

graph::ResourceHandle forwardRecipe(graph::RenderGraph& graph, const render::FrameInputs& inputs) {
  passes::ForwardTargets targets;
  targets.depth = graph.createImage("depth", {.format = graph::Format::D32F});
  targets.color = graph.createImage("hdr", {.format = graph::Format::RGBA16F});
  targets.depth = passes::addZPrepass(graph, inputs.view, targets.depth);
  targets = passes::addForwardOpaque(graph, inputs.view, targets);
  if (passes::hasAlphaMode(inputs.view, scene::AlphaMode::Mask)) targets = passes::addAlphaMask(graph, inputs.view, targets);
  if (passes::hasAlphaMode(inputs.view, scene::AlphaMode::Blend))
    targets.color = passes::addAlphaBlend(graph, inputs.view, inputs.cameraPosition, targets);
  for (const auto& post : inputs.view.materials.postPasses()) targets.color = post.declare(graph, targets.color);
  const auto exposure = passes::addExposure(graph, targets.color);
  return passes::addTonemap(graph, targets.color, exposure, inputs.output);
}

}  // namespace sg::plugins
