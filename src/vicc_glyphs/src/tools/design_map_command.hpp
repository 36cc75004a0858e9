#pragma once
// "vicc_glyph design-map": one glyph of a design per row of a table, placed by longitude and
// latitude on one PNG (the thesis's map figures, without the base map).

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runDesignMapCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vicc_glyphs::tools
