#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

#include <shadelgraph/shadel/hash64.hpp>
#include <shadelgraph/shadel/id_map_cache.hpp>

namespace sg::shadel {
namespace {

constexpr char kMagic[8] = {'S', 'G', 'I', 'D', 'M', 'A', 'P', '\0'};
constexpr uint32_t kByteOrderMark = 0x01020304u;

class Writer {
 public:
  template <class T>
  void put(const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof value);
  }
  template <class T>
  void putArray(const std::vector<T>& values) {
    const auto* p = reinterpret_cast<const uint8_t*>(values.data());
    bytes.insert(bytes.end(), p, p + values.size() * sizeof(T));
  }
  std::vector<uint8_t> bytes;
};

// Reads fail (return false) past the end instead of reading garbage.
class Reader {
 public:
  explicit Reader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  template <class T>
  bool get(T& value) {
    if (bytes_.size() - offset_ < sizeof value) return false;
    std::memcpy(&value, bytes_.data() + offset_, sizeof value);
    offset_ += sizeof value;
    return true;
  }
  template <class T>
  bool getArray(std::vector<T>& values, uint64_t count) {
    if (count > (bytes_.size() - offset_) / sizeof(T)) return false;
    values.resize(count);
    std::memcpy(values.data(), bytes_.data() + offset_, count * sizeof(T));
    offset_ += count * sizeof(T);
    return true;
  }
  size_t offset() const { return offset_; }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t offset_ = 0;
};

void putStats(Writer& w, const IdMapLevelStats& s) {
  w.put(s.size);
  for (uint64_t v : {s.normalTexels, s.conservativeTexels, s.claimedTexels, s.dilatedTexels, s.emptyTexels}) w.put(v);
  for (uint32_t v : {s.owningTriangles, s.orphanTriangles, s.zeroAreaUncovered}) w.put(v);
}

bool getStats(Reader& r, IdMapLevelStats& s) {
  return r.get(s.size) && r.get(s.normalTexels) && r.get(s.conservativeTexels) && r.get(s.claimedTexels) &&
         r.get(s.dilatedTexels) && r.get(s.emptyTexels) && r.get(s.owningTriangles) && r.get(s.orphanTriangles) &&
         r.get(s.zeroAreaUncovered);
}

std::string hex(uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) s[static_cast<size_t>(i)] = digits[v & 15];
  return s;
}

}  // namespace

std::filesystem::path defaultIdMapCacheDirectory() {
  if (const char* dir = std::getenv("SG_CACHE_DIR"); dir && *dir) return std::filesystem::path(dir) / "idmaps";
  if (const char* dir = std::getenv("XDG_CACHE_HOME"); dir && *dir)
    return std::filesystem::path(dir) / "shadelgraph" / "idmaps";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "shadelgraph" / "idmaps";
  return std::filesystem::temp_directory_path() / "shadelgraph-idmaps";
}

uint64_t idMapKey(const scene::Mesh& mesh, const scene::ChartVerdict& chart, const IdMapOptions& options) {
  Hash64 hash;
  hash.text("shadelgraph triangle-ID map").value(kIdMapFormatVersion);
  hash.value(options.level0Size).value(options.minLevelSize).value(options.dilation).value(uint8_t{options.claimOrphans});
  hash.value(chart.uvSet).value(chart.tileOffset.x).value(chart.tileOffset.y);
  hash.value(uint64_t{mesh.primitives.size()});
  for (const scene::Primitive& primitive : mesh.primitives) {
    hash.values(std::span<const glm::vec3>(primitive.positions));
    hash.values(std::span<const glm::vec2>(primitive.uvs(chart.uvSet == 1 ? 1 : 0)));
    hash.values(std::span<const uint32_t>(primitive.indices));
  }
  return hash.digest();
}

IdMapCache::IdMapCache(std::filesystem::path directory) : directory_(std::move(directory)) {}

std::filesystem::path IdMapCache::fileFor(uint64_t key) const { return directory_ / (hex(key) + ".idmap"); }

TriangleIdMap IdMapCache::loadOrBake(const scene::Mesh& mesh, const scene::ChartVerdict& chart,
                                     const IdMapOptions& options) {
  const uint64_t key = idMapKey(mesh, chart, options);
  if (!directory_.empty()) {
    if (std::optional<TriangleIdMap> cached = read(key, options)) {
      ++stats_.diskHits;
      return std::move(*cached);
    }
  }
  TriangleIdMap map = bakeTriangleIdMap(mesh, chart, options);
  ++stats_.bakes;
  if (!directory_.empty() && !write(key, map)) ++stats_.writeFailures;
  return map;
}

std::optional<TriangleIdMap> IdMapCache::read(uint64_t key, const IdMapOptions& options) {
  const std::filesystem::path file = fileFor(key);
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return std::nullopt;
  std::vector<uint8_t> bytes;
  {
    std::ifstream in(file, std::ios::binary);
    if (in) bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  const auto reject = [&]() -> std::optional<TriangleIdMap> {
    ++stats_.rejectedFiles;
    return std::nullopt;
  };
  // The checksum covers everything before it.
  if (bytes.size() < sizeof kMagic + sizeof(uint64_t)) return reject();
  uint64_t storedChecksum;
  std::memcpy(&storedChecksum, bytes.data() + bytes.size() - sizeof storedChecksum, sizeof storedChecksum);
  if (Hash64().bytes(bytes.data(), bytes.size() - sizeof storedChecksum).digest() != storedChecksum) return reject();

  Reader r(bytes);
  char magic[8];
  uint32_t version = 0, byteOrder = 0, level0Size = 0, levelCount = 0, primitiveCount = 0;
  uint64_t storedKey = 0;
  TriangleIdMap map;
  for (char& c : magic)
    if (!r.get(c)) return reject();
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) return reject();
  if (!r.get(version) || version != kIdMapFormatVersion || !r.get(byteOrder) || byteOrder != kByteOrderMark)
    return reject();
  if (!r.get(storedKey) || storedKey != key) return reject();
  if (!r.get(level0Size) || !r.get(levelCount) || !r.get(map.triangleCount) || !r.get(map.zeroAreaTriangles) ||
      !r.get(primitiveCount))
    return reject();
  map.levels = makeDetailLevels(options.level0Size, options.minLevelSize);
  if (map.levels != DetailLevels{level0Size, levelCount}) return reject();
  if (primitiveCount > map.triangleCount + 1'000'000u) return reject();
  map.stats.resize(levelCount);
  for (IdMapLevelStats& stats : map.stats)
    if (!getStats(r, stats)) return reject();
  if (!r.getArray(map.primitiveTriangleBase, primitiveCount)) return reject();
  uint64_t texelCount = 0;
  for (uint32_t l = 0; l < levelCount; ++l) {
    if (map.stats[l].size != map.levels.levelSize(l)) return reject();
    map.levelOffsets.push_back(texelCount);
    texelCount += uint64_t{map.levels.levelSize(l)} * map.levels.levelSize(l);
  }
  if (!r.getArray(map.texels, texelCount)) return reject();
  if (r.offset() + sizeof storedChecksum != bytes.size()) return reject();
  for (uint32_t id : map.texels)
    if (id != kNoTriangle && id >= map.triangleCount) return reject();
  return map;
}

bool IdMapCache::write(uint64_t key, const TriangleIdMap& map) const {
  Writer w;
  for (char c : kMagic) w.put(c);
  w.put(kIdMapFormatVersion);
  w.put(kByteOrderMark);
  w.put(key);
  w.put(map.levels.level0Size);
  w.put(map.levels.levelCount);
  w.put(map.triangleCount);
  w.put(map.zeroAreaTriangles);
  w.put(static_cast<uint32_t>(map.primitiveTriangleBase.size()));
  for (const IdMapLevelStats& stats : map.stats) putStats(w, stats);
  w.putArray(map.primitiveTriangleBase);
  w.putArray(map.texels);
  w.put(Hash64().bytes(w.bytes.data(), w.bytes.size()).digest());

  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  const std::filesystem::path file = fileFor(key);
  std::filesystem::path temporary = file;
  temporary += ".tmp" + hex(std::random_device{}());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    out.write(reinterpret_cast<const char*>(w.bytes.data()), static_cast<std::streamsize>(w.bytes.size()));
    if (!out.good()) {
      out.close();
      std::filesystem::remove(temporary, error);
      return false;
    }
  }
  std::filesystem::rename(temporary, file, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    return false;
  }
  return true;
}

}  // namespace sg::shadel
