#pragma once
// Meshes for the geometry hard cases: sub-texel grids, slivers, collapsed and
// mirrored UVs, made from the procedural primitives or directly.
#include <shadelgraph/scene/mesh.hpp>

namespace sg::test {

// Every triangle gets its own three vertices (so one triangle's UVs can change alone).
scene::Primitive unshared(const scene::Primitive& p);
// Collapses the UVs of every `every`-th triangle to its UV centroid (zero UV area).
scene::Primitive collapseUvs(scene::Primitive p, size_t every);
// Mirrors U (u -> 1 - u): every UV triangle turns clockwise; tangents follow (+U is now -tangent).
scene::Primitive mirrorU(scene::Primitive p);
// A disc of radius 1 in XZ facing +Y as a fan of `segments` slivers around its centre; UV: the disc in [0,1]².
scene::Primitive makeSliverDisc(int segments);
// A width x depth plane (XZ, +Y) cut into `strips` quads along X: triangles `strips` times thinner than long.
scene::Primitive makeSliverStrips(float width, float depth, int strips);

}  // namespace sg::test
