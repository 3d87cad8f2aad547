#pragma once
// Clustered light culling: the light grid (framework/render/shaders/light_grid.h)
// of a frame with many lights, one compute pass, read by every light loop.
#include <span>

#include <glm/glm.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/scene_view.hpp>
#include <shadelgraph/render/shaders/light_grid.h>

namespace sg::passes {

// The grid of a `width`×`height` frame whose visible draws have these world
// bounding spheres: tiles of kLightGridTilePixels (at most kLightGridMaxTiles
// per axis), kLightGridSlices geometric slices of clip w between the spheres'
// nearest and farthest clip w, min(lights, kLightGridMaxPerCluster) index slots per cluster.
shader::SgLightGridHeader lightGridFor(uint32_t width, uint32_t height, const glm::mat4& viewProjection,
                                       std::span<const glm::vec4> visibleSpheres, uint32_t lightCount);
// Bytes of a grid buffer with that header.
uint64_t lightGridBytes(const shader::SgLightGridHeader& grid);

// The pass "light-cull" writing a new grid; `view`: the frame uniforms and lights.
graph::ResourceHandle addLightCull(graph::RenderGraph& graph, const render::SceneView& view,
                                   const shader::SgLightGridHeader& grid, uint32_t lightCount);
gpu::ComputePipelineDesc lightCullPipeline();

}  // namespace sg::passes
