#include "model_path.hpp"

#include <stdexcept>

#include "vicc_paths/package_share.hpp"

namespace vicc_glyphs::tools {

std::string findDefaultPerceptionModel(const std::string& option) {
  try {
    // share/vicc_glyphs of the devel or install space that holds vicc_glyph.
    return vicc_paths::packageDataPath("vicc_glyphs", "config/perception_model.yaml",
                                       reinterpret_cast<const void*>(&findDefaultPerceptionModel))
        .string();
  } catch (const std::exception& e) {
    throw std::runtime_error("the default perception model was not found (" +
                             std::string(e.what()) + "); give --" + option + " MODEL.yaml");
  }
}

std::string perceptionModelPathOrDefault(const std::string& given, const std::string& option) {
  return given.empty() ? findDefaultPerceptionModel(option) : given;
}

}  // namespace vicc_glyphs::tools
