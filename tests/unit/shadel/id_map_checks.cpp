#include "id_map_checks.hpp"

#include <deque>
#include <unordered_set>

#include <shadelgraph/shadel/id_map_level.hpp>

namespace sg::shadel::test {

LevelOwnership checkIdMapLevel(const TriangleIdMap& map, uint32_t level, const ChartTriangles& chart, bool dilated) {
  const uint32_t size = map.levels.levelSize(level);
  const std::span<const uint32_t> ids = map.level(level);
  std::vector<std::vector<uint32_t>> touched(chart.size());
  std::vector<uint32_t> owned(chart.size(), 0);
  const IdMapLevel geometry(chart, size);  // for what each triangle touches, not for its results
  for (uint32_t t = 0; t < chart.size(); ++t) {
    if (chart.zeroArea(t)) continue;
    geometry.forEachTouched(t, [&](uint32_t x, uint32_t y) { touched[t].push_back(y * size + x); });
    EXPECT_FALSE(touched[t].empty()) << "every non-zero-area triangle touches a texel";
    for (uint32_t texel : touched[t]) {
      EXPECT_NE(ids[texel], kNoTriangle) << "level " << level << ": texel " << texel % size << ", " << texel / size
                                         << " touched by triangle " << t << " is empty";
      if (ids[texel] == t) ++owned[t];
      if (!dilated) continue;
      const int x = static_cast<int>(texel % size), y = static_cast<int>(texel / size), n = static_cast<int>(size);
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if (x + dx >= 0 && y + dy >= 0 && x + dx < n && y + dy < n) {
            EXPECT_NE(ids[static_cast<size_t>((y + dy) * n + x + dx)], kNoTriangle)
                << "level " << level << ": neighbour of a chart texel is empty";
          }
    }
  }
  LevelOwnership result;
  for (size_t t = 0; t < chart.size(); ++t) {
    if (chart.zeroArea(t)) continue;
    if (owned[t] > 0) {
      ++result.owning;
      continue;
    }
    ++result.orphans;
    // Alternating search: texels the orphan touches, their owners (who must
    // hold only that one texel), the texels those touch, ...
    std::unordered_set<uint32_t> seenTriangles{static_cast<uint32_t>(t)}, seenTexels;
    std::deque<uint32_t> queue{static_cast<uint32_t>(t)};
    while (!queue.empty()) {
      const uint32_t triangle = queue.front();
      queue.pop_front();
      for (uint32_t texel : touched[triangle]) {
        if (!seenTexels.insert(texel).second) continue;
        const uint32_t owner = ids[texel];
        if (owner == triangle || owner >= chart.size()) continue;
        if (owned[owner] >= 2) {
          ADD_FAILURE() << "level " << level << ": orphan " << t << " could own a texel via triangle " << owner;
          return result;
        }
        if (seenTriangles.insert(owner).second) queue.push_back(owner);
      }
    }
    EXPECT_LT(seenTexels.size(), seenTriangles.size()) << "Hall's condition must fail for orphan " << t;
  }
  return result;
}

}  // namespace sg::shadel::test
