#pragma once
// "vicc_glyph check-design": builds every level combination of a design and reports those that
// fail (an error, or curves that cross as drawn), before the glyph server meets them.

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runCheckDesignCommand(const std::vector<std::string>& args, std::ostream& out,
                          std::ostream& err);

}  // namespace vicc_glyphs::tools
