#include "z_prepass_rule.hpp"

namespace sg::passes {

bool zPrepassPays(uint64_t opaqueTriangles, uint64_t pixels) {
  if (pixels == 0) return false;  // nothing to shade twice
  return double(opaqueTriangles) < kZPrepassMaxTrianglesPerPixel * double(pixels);
}

}  // namespace sg::passes
