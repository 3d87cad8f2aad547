// Stable allocation (issue 15) on the device, validation and synchronization
// validation on: a chunk that stays marked keeps its storage address from
// frame to frame (read back from the GPU's chunk slots), chunks that stop
// being marked free theirs, newly marked ones take free ones, and a storage
// too small for what is marked degrades (overflow, the adjuster's bias)
// without two chunks ever sharing storage.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include <shadelgraph/image/metrics.hpp>
#include <shadelgraph/scene/default_scene.hpp>

#include "decoupled_session.hpp"

namespace sg::test {
namespace {

constexpr uint32_t kSize = 96;
using Addresses = std::map<uint64_t, uint32_t>;  // entry * 64 + chunk -> physical chunk

plugins::DecoupledSettings settingsAt(uint32_t rate) {
  return {.storageChunks = 8192, .fixedBias = 0.0f, .shadeRate = rate};
}

// No two chunks share storage, and all of it is inside the storage's capacity.
void expectDistinctAndInside(const Addresses& addresses, uint32_t capacity, const std::string& what) {
  std::set<uint32_t> physical;
  for (const auto& [chunk, address] : addresses) {
    EXPECT_LT(address, capacity) << what << ": chunk " << chunk;
    EXPECT_TRUE(physical.insert(address).second) << what << ": physical chunk " << address << " stored twice";
  }
}

class StableAllocation : public ::testing::TestWithParam<uint32_t> {};

// A static camera for 10 frames: every stored chunk keeps its address, at
// rate 1 (everything reshaded every frame, in place) and at rate 4.
TEST_P(StableAllocation, StaticCameraKeepsEveryChunkAddress) {
  Session s(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, settingsAt(GetParam()));
  Addresses first;
  for (int frame = 0; frame < 10; ++frame) {
    s.render(kSize, panCamera(0));
    const auto st = s.stats();
    const Addresses addresses = s.chunkAddresses();
    EXPECT_EQ(st.counters.compositeMisses, 0u) << "frame " << frame;
    EXPECT_EQ(addresses.size(), st.counters.chunksAllocated) << "frame " << frame << ": every stored chunk has a slot";
    expectDistinctAndInside(addresses, st.capacityChunks, "frame " + std::to_string(frame));
    if (frame == 0) {
      first = addresses;
      ASSERT_GT(first.size(), 0u);
      continue;
    }
    size_t moved = 0;
    for (const auto& [chunk, address] : first) moved += addresses.count(chunk) && addresses.at(chunk) == address ? 0 : 1;
    EXPECT_EQ(moved, 0u) << "frame " << frame << ": chunks not at their frame-0 address";
    EXPECT_EQ(addresses.size(), first.size()) << "frame " << frame;
    if (!st.shadeFrame) { EXPECT_EQ(st.counters.chunksShaded, 0u) << "frame " << frame; }
  }
}

INSTANTIATE_TEST_SUITE_P(Rates, StableAllocation, ::testing::Values(1u, 4u),
                         [](const ::testing::TestParamInfo<uint32_t>& rate) {
                           return "Rate" + std::to_string(rate.param);
                         });

// A small pan at rate 8: the chunks marked in both frames keep their
// addresses; only the chunks that became marked get storage (free addresses,
// none a kept chunk's), only those that stopped being marked lose theirs; the
// fill shades exactly the newly stored chunks and reuses the kept ones.
TEST(StableAllocationPan, FreesAndAllocatesOnlyTheChunksThatChanged) {
  Session s(scene::makeDefaultScene(64), scene::ShadingMode::Decoupled, settingsAt(8));
  Addresses previous;
  size_t allocatedTotal = 0, freedTotal = 0, keptTotal = 0;
  for (int frame = 0; frame < 8; ++frame) {
    s.render(kSize, panCamera(frame, 0.05f));
    const auto st = s.stats();
    const Addresses addresses = s.chunkAddresses();
    const std::string what = "frame " + std::to_string(frame);
    EXPECT_EQ(st.counters.compositeMisses, 0u) << what;
    EXPECT_EQ(st.counters.overflowChunks, 0u) << what;
    expectDistinctAndInside(addresses, st.capacityChunks, what);
    if (frame > 0) {
      size_t kept = 0, moved = 0, allocated = 0, freed = 0;
      for (const auto& [chunk, address] : addresses) {
        const auto before = previous.find(chunk);
        if (before == previous.end()) {
          ++allocated;
        } else {
          ++kept;
          moved += before->second == address ? 0 : 1;
        }
      }
      for (const auto& [chunk, address] : previous) freed += addresses.count(chunk) ? 0 : 1;
      EXPECT_EQ(moved, 0u) << what << ": chunks marked in both frames that changed address";
      EXPECT_EQ(st.counters.chunksShaded, allocated) << what << ": the fill shades the newly stored chunks only";
      EXPECT_EQ(st.counters.chunksReused, kept) << what << ": and keeps the rest where it is";
      allocatedTotal += allocated;
      freedTotal += freed;
      keptTotal += kept;
    }
    previous = addresses;
  }
  EXPECT_GT(allocatedTotal, 0u) << "the pan must uncover chunks";
  EXPECT_GT(freedTotal, 0u) << "and leave some";
  EXPECT_GT(keptTotal, 10 * allocatedTotal) << "a small pan keeps most chunks";
}

// The gold sphere turns decoupled at frame 3 (rate 8): it gets shadel space,
// so the owned remap entries change; every other object's chunks keep their
// addresses (carried over to the new layout) and their shading (reused).
TEST(StableAllocationPan, ObjectTurningDecoupledKeepsTheOthersAddresses) {
  const auto scene = scene::makeDefaultScene(64);
  Session s(scene, scene::ShadingMode::Decoupled, settingsAt(8));
  const uint32_t sphere = instanceNamed(s.scene(), "gold sphere");
  s.renderer().setObjectMode(sphere, scene::ShadingMode::Forward);
  Addresses before;
  for (int frame = 0; frame < 5; ++frame) {
    if (frame == 3) s.renderer().setObjectMode(sphere, scene::ShadingMode::Decoupled);
    s.render(kSize, panCamera(0));
    const auto st = s.stats();
    const Addresses addresses = s.chunkAddresses();
    const std::string what = "frame " + std::to_string(frame);
    EXPECT_EQ(st.counters.compositeMisses, 0u) << what;
    expectDistinctAndInside(addresses, st.capacityChunks, what);
    if (frame == 3) {
      size_t moved = 0;
      for (const auto& [chunk, address] : before) moved += addresses.count(chunk) && addresses.at(chunk) == address ? 0 : 1;
      EXPECT_EQ(moved, 0u) << "chunks of the other objects that lost or changed their address";
      EXPECT_GT(addresses.size(), before.size()) << "the sphere's chunks were added";
      EXPECT_EQ(st.counters.chunksReused, before.size()) << "the others' shading is kept";
      EXPECT_EQ(st.counters.chunksShaded, addresses.size() - before.size()) << "the sphere is filled";
    }
    before = addresses;
  }
}

// Storage for a fraction of what is marked, the adjuster deciding the bias
// (rate 4 and rate 1 side by side): the first frames overflow, the bias
// rises, and from then on nothing overflows or is missed, no two chunks
// share storage, and rate 4 shows rate 1's image (no stale or foreign
// shading left in a reused slot).
TEST(StableAllocationPressure, TinyStorageDegradesWithoutCorruption) {
  const auto scene = scene::makeDefaultScene(64);
  const plugins::DecoupledSettings tiny{.storageChunks = 48, .shadeRate = 4};
  plugins::DecoupledSettings tinyRate1 = tiny;
  tinyRate1.shadeRate = 1;
  Session n(scene, scene::ShadingMode::Decoupled, tiny);
  Session one(scene, scene::ShadingMode::Decoupled, tinyRate1);
  uint64_t overflowed = 0;
  for (int frame = 0; frame < 14; ++frame) {
    const auto expected = one.render(kSize, panCamera(0));
    const auto image = n.render(kSize, panCamera(0));
    const auto st = n.stats();
    const std::string what = "frame " + std::to_string(frame);
    expectDistinctAndInside(n.chunkAddresses(), st.capacityChunks, what);
    EXPECT_EQ(st.counters.chunksAllocated + st.counters.overflowChunks, st.counters.chunksMarked) << what;
    overflowed += st.counters.overflowChunks;
    if (frame >= 8) {
      EXPECT_EQ(st.counters.overflowChunks, 0u) << what << " (bias " << st.bias << ")";
      EXPECT_EQ(st.counters.compositeMisses, 0u) << what;
      EXPECT_FLOAT_EQ(st.bias, one.stats().bias) << what;
      const auto diff = image::compareRgba8(expected.rgba8, image.rgba8);
      EXPECT_EQ(diff.maxAbs, 0) << what << ": PSNR " << diff.psnr << " dB against rate 1";
    }
  }
  EXPECT_GT(overflowed, 0u) << "the storage must be too small at first";
}

}  // namespace
}  // namespace sg::test
