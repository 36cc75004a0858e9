#include "model_path.hpp"

#include "vicc_paths/package_share.hpp"

namespace vicc_glyphs::tools {

std::string defaultPerceptionModelPath() {
  // share/vicc_glyphs of the devel or install space that holds vicc_glyph.
  return vicc_paths::packageDataPath("vicc_glyphs", "config/perception_model.yaml",
                                     reinterpret_cast<const void*>(&defaultPerceptionModelPath))
      .string();
}

}  // namespace vicc_glyphs::tools
