#pragma once
// Every depth frame allocates pyramids and maps of a few hundred kB. glibc hands blocks that
// large back to the kernel when they are freed, so the next frame faults the same memory in
// again page by page (on the benchmark VM: 19 k page faults on a 178-frame bag, 7.5 % of the
// CPU time). Processes that track call this once at start to keep freed frame memory.

namespace vicc_tracking {

/// Raises glibc's mmap and trim thresholds (malloc stays the allocator). Returns false when
/// the C library refuses (then nothing changed).
bool keepFreedFrameMemory();

}  // namespace vicc_tracking
