// The on-disk triangle-ID map cache.
#include <fstream>

#include <gtest/gtest.h>

#include <shadelgraph/scene/uv_chart.hpp>
#include <shadelgraph/shadel/id_map_cache.hpp>

#include "shadel_test_support.hpp"

namespace sg::shadel {
namespace {

struct Fixture {
  scene::Mesh mesh = test::meshWithUvs({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.4f}},
                                       {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4});
  scene::ChartVerdict chart = scene::analyzeUvSet(mesh, 0);
  IdMapOptions options;
  Fixture() { options.level0Size = 64; }
};

void expectSameMap(const TriangleIdMap& a, const TriangleIdMap& b) {
  EXPECT_EQ(a.levels, b.levels);
  EXPECT_EQ(a.triangleCount, b.triangleCount);
  EXPECT_EQ(a.zeroAreaTriangles, b.zeroAreaTriangles);
  EXPECT_EQ(a.primitiveTriangleBase, b.primitiveTriangleBase);
  EXPECT_EQ(a.levelOffsets, b.levelOffsets);
  EXPECT_EQ(a.texels, b.texels);
  EXPECT_EQ(a.stats, b.stats);
}

TEST(IdMapCache, SecondLoadComesFromDisk) {
  test::TempDir dir;
  Fixture f;
  ASSERT_TRUE(f.chart.unique) << f.chart.reason;
  IdMapCache first(dir.path());
  const TriangleIdMap baked = first.loadOrBake(f.mesh, f.chart, f.options);
  EXPECT_EQ(first.stats().bakes, 1u);
  EXPECT_EQ(first.stats().diskHits, 0u);
  EXPECT_TRUE(std::filesystem::exists(first.fileFor(idMapKey(f.mesh, f.chart, f.options))));
  // A new cache object (a new process, as far as it knows) reads the file.
  IdMapCache second(dir.path());
  const TriangleIdMap loaded = second.loadOrBake(f.mesh, f.chart, f.options);
  EXPECT_EQ(second.stats().diskHits, 1u);
  EXPECT_EQ(second.stats().bakes, 0u);
  expectSameMap(baked, loaded);
  expectSameMap(loaded, bakeTriangleIdMap(f.mesh, f.chart, f.options));
}

TEST(IdMapCache, KeyCoversMeshChartAndOptions) {
  Fixture f;
  const uint64_t key = idMapKey(f.mesh, f.chart, f.options);
  EXPECT_EQ(key, idMapKey(f.mesh, f.chart, f.options));
  IdMapOptions other = f.options;
  other.dilation = 2;
  EXPECT_NE(key, idMapKey(f.mesh, f.chart, other));
  other = f.options;
  other.level0Size = 128;
  EXPECT_NE(key, idMapKey(f.mesh, f.chart, other));
  scene::Mesh moved = f.mesh;
  moved.primitives[0].uv0[4].x += 1e-6f;
  EXPECT_NE(key, idMapKey(moved, f.chart, f.options));
  moved = f.mesh;
  moved.primitives[0].positions[0].z = 1.0f;
  EXPECT_NE(key, idMapKey(moved, f.chart, f.options));
  moved = f.mesh;
  std::swap(moved.primitives[0].indices[0], moved.primitives[0].indices[1]);
  EXPECT_NE(key, idMapKey(moved, f.chart, f.options));
  scene::ChartVerdict shifted = f.chart;
  shifted.tileOffset = glm::vec2(1, 0);
  EXPECT_NE(key, idMapKey(f.mesh, shifted, f.options));
}

class CorruptCacheFile : public ::testing::TestWithParam<int> {};

TEST_P(CorruptCacheFile, IsIgnoredAndRebuilt) {
  test::TempDir dir;
  Fixture f;
  const TriangleIdMap expected = IdMapCache(dir.path()).loadOrBake(f.mesh, f.chart, f.options);
  const std::filesystem::path file = IdMapCache(dir.path()).fileFor(idMapKey(f.mesh, f.chart, f.options));
  std::vector<char> bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 1000u);
  switch (GetParam()) {
    case 0: bytes[bytes.size() / 2] ^= 0x10; break;  // one flipped bit among the texels
    case 1: bytes.resize(bytes.size() / 3); break;    // truncated
    case 2: bytes[0] = 'X'; break;                    // not our format
    case 3: bytes.clear(); break;                     // empty
    case 4: bytes[8] = 99; break;                     // another format version
  }
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));

  IdMapCache cache(dir.path());
  const TriangleIdMap rebuilt = cache.loadOrBake(f.mesh, f.chart, f.options);
  EXPECT_EQ(cache.stats().rejectedFiles, 1u);
  EXPECT_EQ(cache.stats().bakes, 1u);
  EXPECT_EQ(cache.stats().diskHits, 0u);
  expectSameMap(rebuilt, expected);
  // The rebuilt file is whole again.
  IdMapCache again(dir.path());
  expectSameMap(again.loadOrBake(f.mesh, f.chart, f.options), expected);
  EXPECT_EQ(again.stats().diskHits, 1u);
}

// The damage each parameter does, in the switch's order.
std::string damageName(const ::testing::TestParamInfo<int>& info) {
  static const char* const kNames[] = {"FlippedBit", "Truncated", "NotOurFormat", "Empty", "OtherVersion"};
  return kNames[info.param];
}
INSTANTIATE_TEST_SUITE_P(Damage, CorruptCacheFile, ::testing::Range(0, 5), damageName);

TEST(IdMapCache, EmptyDirectoryDisablesCachingAndUnwritableDirectoryStillBakes) {
  Fixture f;
  IdMapCache none{std::filesystem::path()};
  none.loadOrBake(f.mesh, f.chart, f.options);
  none.loadOrBake(f.mesh, f.chart, f.options);
  EXPECT_EQ(none.stats().bakes, 2u);
  EXPECT_EQ(none.stats().writeFailures, 0u);
  test::TempDir dir;
  const std::filesystem::path blocker = dir.path() / "file";
  std::ofstream(blocker) << "not a directory";
  IdMapCache unwritable(blocker / "idmaps");
  const TriangleIdMap map = unwritable.loadOrBake(f.mesh, f.chart, f.options);
  EXPECT_EQ(unwritable.stats().writeFailures, 1u);
  EXPECT_EQ(map.triangleCount, 4u);
}

TEST(IdMapCache, DefaultDirectoryFollowsSgCacheDir) {
  const char* old = std::getenv("SG_CACHE_DIR");
  const std::string saved = old ? old : "";
  ::setenv("SG_CACHE_DIR", "/tmp/sg-cache-test", 1);
  EXPECT_EQ(defaultIdMapCacheDirectory(), std::filesystem::path("/tmp/sg-cache-test/idmaps"));
  if (old) {
    ::setenv("SG_CACHE_DIR", saved.c_str(), 1);
  } else {
    ::unsetenv("SG_CACHE_DIR");
  }
}

}  // namespace
}  // namespace sg::shadel
