#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstring>
#include <memory>

#include "vicc_glyphs/render/process_heap.hpp"

namespace vicc_glyphs {
namespace {

long minorFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// Allocates, fills and frees a block of `bytes`; returns the page faults that took.
long faultsOfAFilledBlock(std::size_t bytes) {
  const long before = minorFaults();
  {
    std::unique_ptr<char[]> block(new char[bytes]);
    std::memset(block.get(), 1, bytes);
    volatile char sink = block[bytes / 2];
    (void)sink;
  }
  return minorFaults() - before;
}

TEST(ProcessHeapTest, AFreedLargeBlockIsReusedWithoutFreshPages) {
#if defined(__GLIBC__)
  ASSERT_TRUE(keepFreedMemoryForReuse());
  constexpr std::size_t kBytes = 8u << 20;  // 2048 pages of 4 KiB
  faultsOfAFilledBlock(kBytes);             // the heap grows once
  // Without the setting, the same block is mapped afresh and faults on each of its pages.
  EXPECT_LT(faultsOfAFilledBlock(kBytes), 100);
#else
  EXPECT_FALSE(keepFreedMemoryForReuse());
#endif
}

}  // namespace
}  // namespace vicc_glyphs
