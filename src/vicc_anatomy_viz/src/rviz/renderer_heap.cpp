#include "vicc_anatomy_viz/rviz/renderer_heap.hpp"

#include <malloc.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace vicc_anatomy_viz::rviz_plugin {

bool isSoftwareRenderer(const std::string& renderer) {
  std::string lower = renderer;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* name : {"llvmpipe", "softpipe", "swrast"})
    if (lower.find(name) != std::string::npos) return true;
  return false;
}

bool keepFreedHeapForRendering() {
  if (std::getenv("MALLOC_TRIM_THRESHOLD_")) return false;
  return mallopt(M_TRIM_THRESHOLD, static_cast<int>(kRendererTrimThresholdBytes)) == 1;
}

}  // namespace vicc_anatomy_viz::rviz_plugin
