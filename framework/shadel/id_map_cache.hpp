#pragma once
// Triangle-ID maps cached on disk, keyed by a hash of what they are baked
// from: positions, the chart's UVs (set and tile offset), indices, the
// options and the file format version. A file is used only if its header,
// key, sizes and checksum all agree; anything else (truncated, damaged, an
// older format, a hash collision's different sizes) is ignored, rebaked and
// overwritten. Files are written to a temporary name and renamed, so a
// crashed or concurrent writer never leaves half a file under the real name.
#include <cstdint>
#include <filesystem>
#include <optional>

#include <shadelgraph/shadel/triangle_id_map.hpp>

namespace sg::shadel {

inline constexpr uint32_t kIdMapFormatVersion = 1;

// $SG_CACHE_DIR/idmaps, else $XDG_CACHE_HOME/shadelgraph/idmaps, else
// ~/.cache/shadelgraph/idmaps (the shader cache's parent, see gpu/shader_compiler.hpp).
std::filesystem::path defaultIdMapCacheDirectory();

// The cache key of a bake.
uint64_t idMapKey(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const IdMapOptions& options);

struct IdMapCacheStats {
  uint64_t diskHits = 0;       // served from a valid file
  uint64_t bakes = 0;          // baked (no file, or a rejected one)
  uint64_t rejectedFiles = 0;  // files present but not trusted
  uint64_t writeFailures = 0;  // could not store a bake (it is still returned)
};

class IdMapCache {
 public:
  // An empty directory disables the cache: every call bakes.
  explicit IdMapCache(std::filesystem::path directory = defaultIdMapCacheDirectory());

  // The cached map, else a fresh bake (stored for next time).
  TriangleIdMap loadOrBake(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const IdMapOptions& options);

  // The file a key is stored in.
  std::filesystem::path fileFor(uint64_t key) const;
  const IdMapCacheStats& stats() const { return stats_; }

 private:
  std::optional<TriangleIdMap> read(uint64_t key, const IdMapOptions& options);
  bool write(uint64_t key, const TriangleIdMap& map) const;

  std::filesystem::path directory_;
  IdMapCacheStats stats_;
};

}  // namespace sg::shadel
