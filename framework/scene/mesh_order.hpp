#pragma once
// Triangle and vertex order of a primitive for the rasterizer (meshoptimizer):
// fewer vertex-shader runs (post-transform cache reuse), less overdraw, and
// vertex numbers in order of first use. The glTF loader applies it at load,
// before anything numbers triangles (ID maps, UV charts), so triangle IDs stay
// consistent. docs/benchmarks.md has the measurements on lavapipe.
#include <shadelgraph/scene/material.hpp>
#include <shadelgraph/scene/mesh.hpp>

namespace sg::scene {

struct MeshOrderOptions {
  bool vertexCache = true;  // meshopt_optimizeVertexCache: triangle order for vertex reuse
  // meshopt_optimizeOverdraw: triangle clusters front-to-back-ish, allowed to
  // cost this factor of vertex-cache efficiency; 0: off.
  float overdrawThreshold = 1.05f;
  // Renumber vertices in order of first use (all attribute arrays). Off: on
  // lavapipe it cut instructions a little but made multi-threaded frames
  // slower (docs/benchmarks.md).
  bool vertexFetch = false;

  bool any() const { return vertexCache || overdrawThreshold > 0.0f || vertexFetch; }
};

// Whether a primitive may be reordered: its triangle order draws nothing
// differently. Not alpha-blended ones (triangles blend in index order) and
// not skinned or morphed ones (their rest pose says little about overdraw,
// and they are small).
bool mayReorder(const Primitive& primitive, const Material& material);

// Reorders the triangles of primitive.indices (each keeps its corners, so its
// winding) and, with vertexFetch, permutes every per-vertex array alike. The
// vertex count stays: unused vertices go last, so bounds stay valid.
void orderForRendering(Primitive& primitive, const MeshOrderOptions& options = {});

}  // namespace sg::scene
