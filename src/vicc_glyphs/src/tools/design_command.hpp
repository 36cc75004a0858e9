#pragma once
// "vicc_glyph design": renders a glyph design (designs/*.yaml) for given data values.

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runDesignCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vicc_glyphs::tools
