#include "core/heap.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <vector>

#include "core/timer.hpp"
#include "support/heap_figures.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace dynanav {
namespace {

// The allocator settings of apps/dynanav/main.cpp keep freed buffers resident; releasing the
// free pages must bring resident memory back down while the live heap is unchanged.
TEST(Heap, FreedPagesStayResidentUntilReleased) {
#if !DYNANAV_GLIBC_HEAP
  GTEST_SKIP() << "the heap figures and the release need glibc's allocator";
#else
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
  constexpr size_t kBlock = 1 << 20, kBlocks = 64;
  const double heap_before = heapInUseMb();
  using Block = std::unique_ptr<char[]>;
  std::vector<Block> blocks;
  for (size_t i = 0; i < kBlocks; ++i) {
    blocks.emplace_back(new char[kBlock]);
    std::memset(blocks.back().get(), int(i), kBlock);  // resident
  }
  // A small block after them keeps the freed ones off the heap's top.
  auto keep = std::make_unique<char[]>(64);
  EXPECT_GT(heapInUseMb(), heap_before + 60.0);
  const double rss_allocated = currentRssMb();
  blocks.clear();
  const double rss_freed = currentRssMb();
  EXPECT_LT(heapInUseMb(), heap_before + 4.0);
  EXPECT_GT(rss_freed, rss_allocated - 8.0) << "freed pages were returned without a release";
  releaseFreeHeapPages();
  EXPECT_LT(currentRssMb(), rss_freed - 48.0);
#endif
}

}  // namespace
}  // namespace dynanav

namespace dynanav {
namespace {

TEST(Heap, PeriodicReleaseWaitsForItsPeriod) {
  PeriodicHeapRelease hourly(3600.0);
  EXPECT_FALSE(hourly());  // the period counts from construction
  EXPECT_FALSE(hourly());
  PeriodicHeapRelease always(0.0);
  EXPECT_TRUE(always());
  EXPECT_TRUE(always());
}

}  // namespace
}  // namespace dynanav
