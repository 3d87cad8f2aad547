#include <shadelgraph/scene/triangulate.hpp>

namespace sg::scene {

std::vector<uint32_t> toTriangleList(std::span<const uint32_t> corners, Topology topology) {
  std::vector<uint32_t> list;
  const size_t n = corners.size();
  switch (topology) {
    case Topology::TriangleList:
      list.assign(corners.begin(), corners.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
      break;
    case Topology::TriangleStrip:
      if (n < 3) break;
      list.reserve((n - 2) * 3);
      for (size_t i = 0; i + 2 < n; ++i) {
        const uint32_t a = corners[i];
        const uint32_t b = corners[i + 1 + i % 2];
        const uint32_t c = corners[i + 2 - i % 2];
        if (a == b || b == c || a == c) continue;
        list.insert(list.end(), {a, b, c});
      }
      break;
    case Topology::TriangleFan:
      if (n < 3) break;
      list.reserve((n - 2) * 3);
      for (size_t i = 0; i + 2 < n; ++i) list.insert(list.end(), {corners[i + 1], corners[i + 2], corners[0]});
      break;
  }
  return list;
}

}  // namespace sg::scene
