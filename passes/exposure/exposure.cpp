#include "exposure.hpp"

#include <cmath>
#include <stdexcept>

#include <shadelgraph/gpu/pass_context.hpp>

namespace sg::passes {
namespace {

// The EV100 kept between frames: one small buffer per renderer.
struct ExposureHistory {
  gpu::Buffer buffer;
};

void check(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("pass 'exposure': parameter " + what);
}

gpu::ImageBinding hdrBinding(const PassContext& ctx, graph::ResourceHandle hdr) {
  return {ctx.image(hdr).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, ctx.device().nearestSampler()};
}

}  // namespace

gpu::ComputePipelineDesc exposureMeterPipeline() {
  return {.shader = {.path = "passes/exposure/exposure_meter.comp"},
          .layout = {.bindings = {{shader::kBindExposureHdr, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                  {shader::kBindExposureMeter, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}}}};
}

gpu::ComputePipelineDesc exposurePipeline(bool manual) {
  if (manual)
    return {.shader = {.path = "passes/exposure/exposure.comp", .defines = {{"SG_EXPOSURE_MANUAL", "1"}}},
            .layout = {.bindings = {{shader::kBindExposure, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                       .pushConstantBytes = sizeof(shader::SgExposureParams)}};
  return {.shader = {.path = "passes/exposure/exposure.comp"},
          .layout = {.bindings = {{shader::kBindExposureHdr, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                  {shader::kBindExposure, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                  {shader::kBindExposureMeter, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}},
                     .pushConstantBytes = sizeof(shader::SgExposureParams)}};
}

shader::SgExposureParams exposureParams(const render::FrameContext& frame) {
  shader::SgExposureParams p{};
  const auto mode = frame.parameter<std::string>("mode");
  check(mode == "auto" || mode == "manual", "'mode' must be \"auto\" or \"manual\", not \"" + mode + "\"");
  p.mode = mode == "manual" ? shader::kExposureManual : shader::kExposureAuto;
  p.ev100 = frame.parameter<float>("ev100");
  p.compensation = frame.parameter<float>("compensation");
  p.adaptation = frame.parameter<float>("adaptation");
  p.minEv100 = frame.parameter<float>("min-ev100");
  p.maxEv100 = frame.parameter<float>("max-ev100");
  check(std::abs(p.ev100) <= 64.0f, "'ev100' must be a number from -64 to 64");
  check(std::abs(p.compensation) <= 64.0f, "'compensation' must be a number from -64 to 64");
  check(p.adaptation > 0.0f && p.adaptation <= 1.0f, "'adaptation' must be in (0, 1]");
  check(std::abs(p.minEv100) <= 64.0f && std::abs(p.maxEv100) <= 64.0f && p.minEv100 <= p.maxEv100,
        "'min-ev100' and 'max-ev100' must be numbers from -64 to 64, min <= max");
  return p;
}

graph::ResourceHandle addExposure(render::FrameContext& frame, graph::ResourceHandle hdr,
                                  const shader::SgExposureParams& params) {
  auto& history = frame.ownState<ExposureHistory>("exposure");
  const auto& in = frame.inputs();
  if (!history.buffer) {
    // Host-visible and zeroed: frames = 0 tells the first frame there is nothing to adapt from.
    history.buffer = gpu::Buffer(in.device.context(), in.device.memory(),
                                 {sizeof(shader::SgExposure), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                  gpu::MemoryLocation::Readback, "exposure history", "exposure", true});
    const shader::SgExposure zero{};
    history.buffer.write(&zero, sizeof zero);
  }
  const graph::ResourceState resting{graph::Layout::General, graph::PipelineStage::AllCommands,
                                     graph::AccessFlag::ShaderStorageRead | graph::AccessFlag::ShaderStorageWrite};
  auto exposure = frame.graph().importPersistentBuffer("exposure history", {.size = sizeof(shader::SgExposure)},
                                                       resting);
  in.executor.bindBuffer(exposure, history.buffer);
  auto& graph = frame.graph();
  if (params.mode == shader::kExposureManual) {
    auto& pass = graph.addPass("exposure", graph::QueueClass::AsyncCompute);
    exposure = pass.write(exposure, graph::Access::StorageReadWrite);
    pass.execute([exposure, params](PassContext& ctx) {
      const auto& pipeline = ctx.device().pipeline("exposure/manual", [] { return exposurePipeline(true); });
      ctx.bind(pipeline, {{shader::kBindExposure, gpu::BufferBinding{ctx.buffer(exposure).handle()}}});
      vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof params, &params);
      vkCmdDispatch(ctx.cmd(), 1, 1, 1);
    });
    return exposure;
  }
  auto meter = graph.createBuffer("exposure meter", {.size = sizeof(float) * shader::kExposureMeterBands});
  auto& metering = graph.addPass("exposure-meter", graph::QueueClass::AsyncCompute);
  metering.read(hdr, graph::Access::Sampled);
  meter = metering.write(meter, graph::Access::StorageWrite);
  metering.execute([hdr, meter](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("exposure-meter", exposureMeterPipeline);
    ctx.bind(pipeline, {{shader::kBindExposureHdr, hdrBinding(ctx, hdr)},
                        {shader::kBindExposureMeter, gpu::BufferBinding{ctx.buffer(meter).handle()}}});
    vkCmdDispatch(ctx.cmd(), shader::kExposureMeterBands, 1, 1);
  });
  auto& pass = graph.addPass("exposure", graph::QueueClass::AsyncCompute);
  pass.read(hdr, graph::Access::Sampled);
  pass.read(meter, graph::Access::StorageRead);
  exposure = pass.write(exposure, graph::Access::StorageReadWrite);
  pass.execute([hdr, meter, exposure, params](PassContext& ctx) {
    const auto& pipeline = ctx.device().pipeline("exposure", [] { return exposurePipeline(false); });
    ctx.bind(pipeline, {{shader::kBindExposureHdr, hdrBinding(ctx, hdr)},
                        {shader::kBindExposure, gpu::BufferBinding{ctx.buffer(exposure).handle()}},
                        {shader::kBindExposureMeter, gpu::BufferBinding{ctx.buffer(meter).handle()}}});
    vkCmdPushConstants(ctx.cmd(), pipeline.layout(), VK_SHADER_STAGE_ALL, 0, sizeof params, &params);
    vkCmdDispatch(ctx.cmd(), 1, 1, 1);
  });
  return exposure;
}

}  // namespace sg::passes
