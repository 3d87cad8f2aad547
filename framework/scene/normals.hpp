#pragma once
// Flat normals for primitives that have none (glTF requires flat shading then).
#include <shadelgraph/scene/mesh.hpp>

namespace sg::scene {

// Gives every triangle its own three vertices (all attributes expanded) and
// sets indices to 0..n-1, so per-face attributes can differ at shared corners.
void deindex(Primitive& primitive);

// De-indexes `primitive` and sets each vertex normal to its triangle's
// (counter-clockwise front) face normal; degenerate triangles get +Z.
void generateFlatNormals(Primitive& primitive);

}  // namespace sg::scene
