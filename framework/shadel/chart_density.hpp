#pragma once
// How evenly a shading chart spreads its shadels over the surface. Level 0
// follows the textures' density on average (level0_resolution.hpp); where a
// chart gives part of the surface far less UV area than the mean (Suzanne's
// TEXCOORD_0: a radial projection that squeezes half the head, the ears
// included, to under 1/30 of the mean density), those triangles get shadels
// much coarser than the rest at every level, and many are smaller than a
// texel: their pixels take a neighbour's extrapolated shading. Raising level 0
// until the sparsest tenth reaches the mean density would take 23x (2^4.5)
// more shadels a side on Suzanne, so such a chart is refused instead: decoupled mode gives the mesh
// an automatic chart (uniform density by construction), auto mode shades it
// forward and says why.
#include <string>

#include <shadelgraph/scene/mesh.hpp>

namespace sg::shadel {

struct ChartDensityOptions {
  double sparseFraction = 0.1;    // the part of the surface (by world area) judged
  double maxLinearSpread = 2.0;   // sqrt(mean / sparse density) above this: uneven
};

struct ChartDensity {
  double worldArea = 0.0;
  double uvArea = 0.0;
  double meanDensity = 0.0;    // UV area per world area over the whole mesh
  double sparseDensity = 0.0;  // the density that sparseFraction of the world area stays at or below
  // How many times coarser (per side) the sparse part is shaded than the mean:
  // sqrt(meanDensity / sparseDensity); infinite when that part has no UV area.
  double linearSpread = 1.0;
  bool even = true;  // linearSpread <= maxLinearSpread
  std::string describe() const;  // e.g. "its sparsest tenth is shaded 23.4x coarser per side than the mean"
};

// Per triangle of `uvSet` (every primitive that has it), UV area / world area,
// weighted by world area. Triangles of zero world area do not count. A mesh
// without that set or without area is `even`.
ChartDensity chartDensity(const scene::Mesh& mesh, int uvSet, const ChartDensityOptions& options = {});

}  // namespace sg::shadel
