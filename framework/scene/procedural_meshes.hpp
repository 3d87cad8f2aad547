#pragma once
// Procedural primitives for built-in scenes. Each has a unique UV chart in
// TEXCOORD_0 (no two triangles overlap in [0,1]^2), so every one of them can
// be shaded decoupled, and analytic tangents for normal mapping.
#include <glm/glm.hpp>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::scene {

// An axis-aligned box centred at the origin; its six faces sit in a 3x2 atlas.
Primitive makeBox(const glm::vec3& size);
// A plane in XZ facing +Y, `subdivisions` quads a side; UV spans the plane.
Primitive makePlane(float width, float depth, int subdivisions);
// A capped cylinder along +Y from y = 0 to `height`; the side takes the lower
// 60% of the chart, the caps two discs above it.
Primitive makeCylinder(float radius, float height, int segments);
// A UV sphere; the poles get one vertex per segment so no UV triangle is degenerate.
Primitive makeSphere(float radius, int segments, int rings);
// A torus around +Y; UV is (angle around the ring, angle around the tube).
Primitive makeTorus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments);

}  // namespace sg::scene
