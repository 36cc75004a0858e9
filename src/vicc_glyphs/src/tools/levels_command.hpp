#pragma once
// "vicc_glyph levels": the level-to-stimulus table of every visual variable of the perception
// model for a glyph of a given size (thesis 6.1.4.3, 6.1.5).

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runLevelsCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vicc_glyphs::tools
