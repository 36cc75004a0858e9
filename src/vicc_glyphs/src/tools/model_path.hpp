#pragma once
// Where the perception model file is found when a subcommand is given no --model.

#include <string>

#include "command_line.hpp"

namespace vicc_glyphs::tools {

/// The package's config/perception_model.yaml in share/vicc_glyphs of the devel or install
/// space that holds vicc_glyph. Throws std::runtime_error when it is not there (a copied or
/// relocated binary): the message says the default model was not found, where it was looked
/// for, and to give `--<option> MODEL.yaml` instead.
std::string findDefaultPerceptionModel(const std::string& option = "model");

/// `given` when a model file was given on the command line, else findDefaultPerceptionModel:
/// call it where errors are reported, after --help and the options are handled.
std::string perceptionModelPathOrDefault(const std::string& given,
                                         const std::string& option = "model");

/// The --model MODEL.yaml option of the subcommands that use the perception model.
inline OptionSpec perceptionModelOption() {
  return {"model", "MODEL.yaml", "perception model (default: config/perception_model.yaml)"};
}

}  // namespace vicc_glyphs::tools
