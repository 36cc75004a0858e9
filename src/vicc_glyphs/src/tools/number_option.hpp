#pragma once
// Real-valued command-line options (the integer parser lives in command_line.hpp).

#include <string>

namespace vicc_glyphs::tools {

/// Parses `text` as a finite number in [minimum, maximum]; throws UsageError naming `option`.
double parseNumber(const std::string& option, const std::string& text, double minimum,
                   double maximum);

}  // namespace vicc_glyphs::tools
