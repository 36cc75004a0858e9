#pragma once
// The shipped perception model and designs, for the design tests.
#include <string>

#include "vicc_glyphs/design/glyph_design.hpp"
#include "vicc_glyphs/perception/perception_model_yaml.hpp"

namespace vicc_glyphs::design::test {

inline const perception::PerceptionModel& model() {
  static const auto loaded = perception::loadPerceptionModel(std::string(VICC_GLYPHS_CONFIG_DIR) +
                                                             "/perception_model.yaml");
  return loaded;
}

inline GlyphDesign shipped(const std::string& name) {
  return loadDesign(std::string(VICC_GLYPHS_DESIGNS_DIR) + "/" + name + ".yaml", model());
}

}  // namespace vicc_glyphs::design::test
