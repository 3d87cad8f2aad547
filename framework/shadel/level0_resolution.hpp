#pragma once
// How fine an object's level 0 is: the shadel density decoupled shading can
// never exceed for it, so it bounds the ID maps and the shadel-space
// rectangles.
//
// The rule, in shadels a side of the [0,1]² chart:
// - texture term: as many shadels per surface area as the finest texture the
//   mesh's materials sample has texels. With R the texture's size, A_tex the
//   UV area of the set it is sampled with and A_chart the shading chart's UV
//   area (sums of |triangle areas|; mirrored halves count twice, as they get
//   the texels twice), R_tex = R * sqrt(A_tex / A_chart): exactly R when the
//   chart is the texture's own UV set;
// - triangle term: enough that the average triangle gets texelsPerTriangle
//   texels: R_tri = sqrt(texelsPerTriangle * triangles / A_chart), which
//   decides for untextured meshes;
// - level 0 = the power of two nearest (in log2) to max(R_tex, R_tri),
//   clamped to [minSize, maxSize].
// - screen term (screenRateLevel0Size, taken as a floor by the caller): as
//   many shadels as the view that first shows the object has pixels on it, so
//   composite's level there is never clamped at a magnified level 0.
#include <cstdint>

#include <glm/glm.hpp>

#include <shadelgraph/scene/scene.hpp>
#include <shadelgraph/scene/uv_chart.hpp>

namespace sg::shadel {

struct Level0Options {
  double texelsPerTriangle = 8.0;
  uint32_t minSize = 64;    // one remap entry
  uint32_t maxSize = 4096;  // a 4K² ID map is 64 MiB for level 0 alone
};

// The finest texture the mesh's materials sample: its larger dimension, and
// the UV set it is sampled with. resolution 0: untextured.
struct MeshTextureDensity {
  uint32_t resolution = 0;
  int uvSet = 0;
};
MeshTextureDensity meshTextureDensity(const scene::Scene& scene, const scene::Mesh& mesh);

uint32_t chooseLevel0Size(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const MeshTextureDensity& texture,
                          const Level0Options& options = {});

// The level 0 at which the mesh, drawn with `world` in a view of `viewProjection`
// and width x height pixels, gets at least one shadel per pixel on its
// *narrow* triangles: those whose smallest UV altitude spans fewer than
// `narrowShadels` shadels at `level0` (a bevel, a crease strip: their shading
// is lost when magnified, while a wide triangle's is only magnified like its
// texture). Each narrow triangle asks for the square root of its pixel area
// over its chart UV area, the others for nothing; the answer is what the
// triangles covering `coverage` of the projected area ask at most (the rest
// are slivers whose UV area is next to nothing), under composite's
// nearest-level rounding (a level up to half a level magnified still reads
// level 0): the power of two at or above R / sqrt(2). Triangles behind the
// camera or outside the view count for nothing; 0 when none asks. Not
// clamped: the caller takes it as a floor under chooseLevel0Size and clamps.
uint32_t screenRateLevel0Size(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const glm::mat4& world,
                              const glm::mat4& viewProjection, uint32_t width, uint32_t height, uint32_t level0,
                              double narrowShadels = 4.0, double coverage = 0.99);

}  // namespace sg::shadel
