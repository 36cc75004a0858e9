#pragma once
// "vicc_glyph fit-model": derives the perception model from survey answers (thesis 6.1.3.3)
// and writes the model file.

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runFitCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vicc_glyphs::tools
