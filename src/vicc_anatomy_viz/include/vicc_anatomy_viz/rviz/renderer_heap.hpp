#pragma once
// Keeps the memory a software rasteriser frees every frame in the process's heap.
//
// Mesa's llvmpipe bins each frame into a "scene" of 64 KB blocks malloc'ed while the frame is
// set up and freed once it is rasterised: tens of MB per frame for the avatar's full status.
// glibc returns the freed top of the heap to the kernel as soon as it exceeds its trim
// threshold (128 KB), so the next frame page-faults all of it back in (zeroed pages; in a VM
// each fault traps to the hypervisor): measured ~800 page faults per frame and half the full
// status's frame rate (bench/avatar/results.md, 2026-12-02 "fps"). A higher trim threshold
// keeps those pages mapped between frames; it only ever keeps what the process already used.

#include <cstddef>
#include <string>

namespace vicc_anatomy_viz::rviz_plugin {

/// The trim threshold set for software rendering: larger than llvmpipe's scene limit (36 MB)
/// with several scenes in flight.
constexpr std::size_t kRendererTrimThresholdBytes = std::size_t{256} << 20;

/// Whether an OpenGL renderer string names a CPU rasteriser (Mesa llvmpipe, softpipe, swrast).
bool isSoftwareRenderer(const std::string& renderer);

/// Raises glibc's heap trim threshold to kRendererTrimThresholdBytes, unless the user chose
/// one (MALLOC_TRIM_THRESHOLD_ in the environment). Process-wide; true if it was set.
bool keepFreedHeapForRendering();

}  // namespace vicc_anatomy_viz::rviz_plugin
