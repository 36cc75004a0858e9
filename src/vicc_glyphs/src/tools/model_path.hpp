#pragma once
// Where the perception model file is found when a subcommand is given no --model.

#include <string>

namespace vicc_glyphs::tools {

/// The package's config/perception_model.yaml (source tree; set at build time).
std::string defaultPerceptionModelPath();

}  // namespace vicc_glyphs::tools
