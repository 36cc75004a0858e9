#include "vicc_tracking/frame_memory.hpp"

#include <malloc.h>

namespace vicc_tracking {

bool keepFreedFrameMemory() {
  // Blocks up to 64 MB come from the heap instead of fresh mmaps, and up to 256 MB of free
  // heap stay with the process: a frame's buffers reuse the previous frame's pages.
  return mallopt(M_MMAP_THRESHOLD, 64 << 20) == 1 && mallopt(M_TRIM_THRESHOLD, 256 << 20) == 1;
}

}  // namespace vicc_tracking
