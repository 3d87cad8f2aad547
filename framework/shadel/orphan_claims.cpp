// Step (3) of triangle-ID map baking: give every triangle that owns no texel
// one it touches, where that is possible at all. This is bipartite matching
// (triangles to texels they touch) started from the coverage result: a texel
// is "free" when its owner has another one, and an orphan searches
// breadth-first along alternating paths for a free texel. Kuhn's argument
// lets failed searches' marks stand until the next success (a triangle from
// which no free texel was reachable stays so while nothing changes), so the
// whole step costs about one sweep over the triangles involved.
#include <algorithm>
#include <deque>
#include <unordered_map>
#include <unordered_set>

#include <shadelgraph/shadel/id_map_level.hpp>
#include <shadelgraph/shadel/triangle_id_map.hpp>

namespace sg::shadel {
namespace {

class OrphanClaims {
 public:
  OrphanClaims(IdMapLevel& level, const ChartTriangles& chart) : level_(level), chart_(chart) {}

  bool claim(uint32_t orphan) {
    if (deadTriangles_.count(orphan)) return false;
    nodes_.clear();
    std::deque<uint32_t> queue;
    std::unordered_set<uint32_t> seenTexels;
    std::unordered_set<uint32_t> seenTriangles{orphan};
    nodes_.push_back({orphan, -1, kNoTriangle});
    queue.push_back(0);
    while (!queue.empty()) {
      const uint32_t node = queue.front();
      queue.pop_front();
      const uint32_t taker = nodes_[node].triangle;
      for (uint32_t texel : touched(taker)) {
        if (deadTexels_.count(texel) || !seenTexels.insert(texel).second) continue;
        const uint32_t owner = level_.owner[texel];
        if (owner == taker) continue;
        if (owner == kNoTriangle || level_.ownedTexels[owner] >= 2) {
          augment(node, texel);
          deadTexels_.clear();  // the matching changed: earlier failures may now succeed
          deadTriangles_.clear();
          return true;
        }
        if (!seenTriangles.insert(owner).second || deadTriangles_.count(owner)) continue;
        nodes_.push_back({owner, static_cast<int32_t>(node), texel});
        queue.push_back(static_cast<uint32_t>(nodes_.size() - 1));
      }
    }
    deadTexels_.insert(seenTexels.begin(), seenTexels.end());
    deadTriangles_.insert(seenTriangles.begin(), seenTriangles.end());
    return false;
  }

 private:
  struct Node {
    uint32_t triangle;
    int32_t parent;       // the node that wants `given` from this one
    uint32_t given;       // this triangle's only texel, wanted by the parent
  };

  // The texels a triangle touches, best first: those normal coverage did not
  // claim, then nearest its UV centroid.
  const std::vector<uint32_t>& touched(uint32_t triangle) {
    auto [it, inserted] = touched_.try_emplace(triangle);
    if (!inserted) return it->second;
    std::vector<uint32_t>& texels = it->second;
    level_.forEachTouched(triangle, [&](uint32_t x, uint32_t y) { texels.push_back(level_.index(x, y)); });
    const auto& uv = chart_.uv[triangle];
    const glm::dvec2 centroid = (uv[0] + uv[1] + uv[2]) / 3.0 * static_cast<double>(level_.size);
    const auto rank = [&](uint32_t texel) {
      const glm::dvec2 d = level_.centre(texel) - centroid;
      return std::pair(level_.source[texel] == TexelSource::Normal, glm::dot(d, d));
    };
    std::sort(texels.begin(), texels.end(), [&](uint32_t a, uint32_t b) { return rank(a) < rank(b); });
    return texels;
  }

  // nodes_[node] takes `texel`; each ancestor then takes the texel its child
  // gave up. Counts: the final owner loses one, the orphan gains one.
  void augment(uint32_t node, uint32_t texel) {
    int32_t current = static_cast<int32_t>(node);
    while (current >= 0) {
      const Node& n = nodes_[static_cast<size_t>(current)];
      const uint32_t previous = level_.owner[texel];
      if (previous != kNoTriangle) --level_.ownedTexels[previous];
      level_.owner[texel] = n.triangle;
      level_.source[texel] = TexelSource::Claimed;
      ++level_.ownedTexels[n.triangle];
      texel = n.given;
      current = n.parent;
    }
  }

  IdMapLevel& level_;
  const ChartTriangles& chart_;
  std::vector<Node> nodes_;
  std::unordered_map<uint32_t, std::vector<uint32_t>> touched_;
  std::unordered_set<uint32_t> deadTexels_, deadTriangles_;
};

}  // namespace

uint32_t claimTexelsForOrphans(IdMapLevel& level, const ChartTriangles& chart) {
  OrphanClaims claims(level, chart);
  uint32_t orphans = 0;
  for (uint32_t t = 0; t < level.triangles.size(); ++t)
    if (!level.zeroArea[t] && level.ownedTexels[t] == 0 && !claims.claim(t)) ++orphans;
  return orphans;
}

}  // namespace sg::shadel
