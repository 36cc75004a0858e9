// renderer_heap: which renderers count as software, and that the raised trim threshold keeps
// a freed frame's worth of 64 KB blocks (llvmpipe's scene memory) in the heap.
#include <gtest/gtest.h>
#include <malloc.h>

#include <cstdlib>
#include <vector>

#include "vicc_anatomy_viz/rviz/renderer_heap.hpp"

namespace {

using namespace vicc_anatomy_viz::rviz_plugin;

TEST(RendererHeap, RecognisesMesasCpuRasterisers) {
  EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(isSoftwareRenderer("Gallium 0.4 on softpipe"));
  EXPECT_TRUE(isSoftwareRenderer("Software Rasterizer (swrast)"));
  EXPECT_FALSE(isSoftwareRenderer("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
  EXPECT_FALSE(isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
  EXPECT_FALSE(isSoftwareRenderer(""));
}

/// Bytes the main arena holds from the kernel (brk) after 32 MB of 64 KB blocks are
/// allocated and freed again, last allocated first (as a scene's blocks are released).
std::size_t arenaAfterAFreedFrame() {
  constexpr std::size_t kBlock = 64 * 1024 + 16, kBlocks = 512;
  std::vector<void*> blocks;
  for (std::size_t i = 0; i < kBlocks; ++i) {
    blocks.push_back(std::malloc(kBlock));
    static_cast<volatile char*>(blocks.back())[0] = 1;
  }
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it) std::free(*it);
  return mallinfo2().arena;
}

TEST(RendererHeap, AFreedFrameStaysInTheHeap) {
  if (std::getenv("MALLOC_TRIM_THRESHOLD_")) GTEST_SKIP() << "the environment sets the threshold";
  ASSERT_TRUE(keepFreedHeapForRendering());
  // Without the threshold glibc trims the freed top back to the kernel (arena ~ before).
  EXPECT_GE(arenaAfterAFreedFrame(), std::size_t{32} << 20);
}

}  // namespace
