#pragma once
// The environment light (a scene's equirectangular HDR image): prefiltered
// once, by two compute passes in the first frame that needs the maps, into
// persistent images every later frame reads without a pass of its own.
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/render/frame_context.hpp>

#include "environment_interface.h"

namespace sg::passes {

// Publishes the frame resources render::kEnvironment*Resource (declared
// persistent images) when the scene names an environment; nothing otherwise.
// The prefilter passes ("environment-downsample", "environment-prefilter")
// are added only until they have run once.
void addEnvironment(render::FrameContext& frame);
gpu::ComputePipelineDesc environmentPrefilterPipeline();

}  // namespace sg::passes
