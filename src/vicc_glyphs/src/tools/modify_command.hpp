#pragma once
// "vicc_glyph modify": PACEMOD contour modifications of an icon (periodic geometric waves,
// colour dashes, inflating/shrinking), rendered to PNG, optionally with the modified DCI and a
// JSON report of what was applied.

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runModifyCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vicc_glyphs::tools
