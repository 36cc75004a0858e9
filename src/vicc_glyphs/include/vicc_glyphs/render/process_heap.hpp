#pragma once
// Heap settings for processes that make glyph after glyph (the glyph server node, the
// vicc_glyph tool, the benchmarks). With glibc's defaults, large blocks (hundreds of kilobytes
// and more: a glyph's sampled contours, the crossing search's buckets, the renderer's fields)
// are handed back to the kernel when freed, and the next glyph's blocks of the same size come as
// fresh pages: one page fault per 4 KiB. For the brain's rectangle-wave glyphs that was a fifth of
// their CPU time before the crossing search kept its buckets
// (src/vicc_glyphs/bench/pacemod/README.md, session 31).

namespace vicc_glyphs {

/// Keeps freed memory in the process's heap for reuse: blocks below 32 MiB come from the heap
/// instead of their own mappings, and up to 256 MiB of free memory at the heap's end stays
/// mapped. The process's resident size then stays near its peak. It changes malloc for the
/// whole process, so libraries do not call it; a node's or a tool's main() may, a nodelet (a
/// process shared with others) must not. Returns false where the C library is not glibc or
/// refuses a setting.
bool keepFreedMemoryForReuse();

}  // namespace vicc_glyphs
