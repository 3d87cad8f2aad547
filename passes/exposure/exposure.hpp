#pragma once
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/frame_context.hpp>

#include "exposure_interface.h"

namespace sg::passes {

// Exposure as EV100, manual or automatic (the log-average luminance of `hdr`,
// adapted across frames), on async compute. Automatic adds "exposure-meter"
// (a log-luminance sum per band of rows, one workgroup each) before
// "exposure". Writes the renderer's persistent exposure buffer
// (shader::SgExposure) and returns its new version.
graph::ResourceHandle addExposure(render::FrameContext& frame, graph::ResourceHandle hdr,
                                  const shader::SgExposureParams& params);
// The pass's parameters, checked (one message naming the bad one).
shader::SgExposureParams exposureParams(const render::FrameContext& frame);
gpu::ComputePipelineDesc exposureMeterPipeline();
gpu::ComputePipelineDesc exposurePipeline(bool manual);

}  // namespace sg::passes
