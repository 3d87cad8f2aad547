#pragma once
// Skinning and morph targets on the GPU: one compute pass that writes the
// deformed vertices of every skinned or morphed object into its own range of
// the scene vertex buffer, from the rest pose, joints, weights and deltas
// uploaded with the scene and this frame's joint matrices and morph weights.
// The buffer is imported into the frame as render::kSceneVerticesResource so
// that every pass that reads geometry orders after it (readSceneGeometry).
#include <shadelgraph/gpu/graph_executor.hpp>
#include <shadelgraph/gpu/pipeline.hpp>
#include <shadelgraph/graph/render_graph.hpp>
#include <shadelgraph/render/gpu_scene.hpp>

namespace sg::passes {

gpu::ComputePipelineDesc skinningPipeline();
// Imports the scene vertex buffer, adds the pass and returns the vertices' new version.
graph::ResourceHandle addSkinning(graph::RenderGraph& graph, gpu::GraphExecutor& executor, const render::GpuScene& scene,
                                  const render::DeformationFrame& frame);

}  // namespace sg::passes
