#pragma once
// "vicc_glyph render": loads a DCI (Orzan XML), SVG icon or PNG, renders it with the multigrid
// renderer and writes a PNG (and optionally the DCI as Orzan XML).

#include <ostream>
#include <string>
#include <vector>

namespace vicc_glyphs::tools {

int runRenderCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace vicc_glyphs::tools
