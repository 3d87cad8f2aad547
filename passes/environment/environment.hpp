#pragma once
// The environment light (a scene's equirectangular HDR image): prefiltered
// once, by two compute passes in the first frame that needs the maps, into
// persistent images every later frame reads without a pass of its own.
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/render/frame_context.hpp>

#include "environment_interface.h"

namespace sg::passes {

// The image itself (RGBA32F texels row by row), a frame resource like the maps.
inline constexpr const char* kEnvironmentImageResource = "environment.image";

// Publishes the frame resources render::kEnvironment*Resource and kEnvironmentImageResource (declared
// persistent images) when the scene names an environment; nothing otherwise.
// The prefilter passes ("environment-downsample", "environment-prefilter")
// are added only until they have run once.
void addEnvironment(render::FrameContext& frame);
gpu::ComputePipelineDesc environmentPrefilterPipeline();

// The environment behind everything: where `depth` is at the far plane, `hdr`
// becomes the image's radiance (times its intensity) in the view direction.
// Declared ("environment-background") only when the scene names an image;
// returns `hdr` unchanged otherwise.
graph::ResourceHandle addEnvironmentBackground(render::FrameContext& frame, graph::ResourceHandle hdr,
                                               graph::ResourceHandle depth);
gpu::ComputePipelineDesc environmentBackgroundPipeline();

}  // namespace sg::passes
