// keepFreedHeapMemory (apps/shadelgraph/heap_policy.cpp): memory a "frame"
// frees comes back to the next one without page faults. Without it glibc
// gives the freed top of the heap to the kernel and every frame faults its
// pages in again (issue 14: a 1000-pass graph compiled fresh, 4.4 ms for 0.7).
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <cstdlib>
#include <memory>
#include <vector>

#include "heap_policy.hpp"

namespace {

long minorFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// 4 MB in 4 KiB blocks (below any mmap threshold: from the heap), each written, then all freed.
void frame() {
  constexpr std::size_t kBlocks = 1024, kBlockBytes = 4096;
  std::vector<std::unique_ptr<char[]>> blocks;
  blocks.reserve(kBlocks);
  for (std::size_t i = 0; i < kBlocks; ++i) {
    blocks.emplace_back(new char[kBlockBytes]);
    static_cast<volatile char*>(blocks.back().get())[0] = 1;
    static_cast<volatile char*>(blocks.back().get())[kBlockBytes - 1] = 1;
  }
}

TEST(HeapPolicy, AFramesFreedMemoryIsReusedWithoutPageFaults) {
#if !defined(__GLIBC__)
  GTEST_SKIP() << "the policy is glibc's";
#else
  sg::app::keepFreedHeapMemory();
  frame();  // the heap grows once
  const long before = minorFaults();
  for (int i = 0; i < 8; ++i) frame();
  // 8 frames of 1024 pages each: the default policy faults about 8000 times here.
  EXPECT_LT(minorFaults() - before, 100);
#endif
}

}  // namespace
