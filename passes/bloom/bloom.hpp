#pragma once
// Bloom (passes/bloom): present only when the scene calls for it
// (bloomCalledFor), between exposure and tonemap.
#include <span>

#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/gpu_scene.hpp>
#include <shadelgraph/scene/scene.hpp>

#include "bloom_interface.h"

namespace sg::passes {

// The emission (cd/m^2) above which a visible object calls for bloom, by default.
inline constexpr float kBloomThreshold = 10.0f;
inline constexpr uint32_t kBloomLevels = 5;

// Luminance (cd/m^2) a material emits at most: its emissive factor's
// luminance times KHR_materials_emissive_strength (an emissive texture only lowers it).
float emittedLuminance(const scene::Material& material);
// Whether a visible draw emits at least `threshold`: its pixels are at least that bright.
bool bloomCalledFor(const scene::Scene& scene, const render::GpuScene& gpuScene, std::span<const uint32_t> visible,
                    float threshold);

// The bloomed HDR colour (a new RGBA16F image): `hdr` plus `strength` times
// the part of it above white after `exposure`, spread over `levels` halvings.
graph::ResourceHandle addBloom(graph::RenderGraph& graph, graph::ResourceHandle hdr, graph::ResourceHandle exposure,
                               float strength, uint32_t levels);
gpu::ComputePipelineDesc bloomPipeline();

}  // namespace sg::passes
