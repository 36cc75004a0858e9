#pragma once
// "k=v,k=v" value lists of the design command line.

#include <map>
#include <string>

namespace vicc_glyphs::design {

/// Parses "name=number,..." ; throws DesignValueError naming the bad entry (no '=', an empty
/// name, a repeated name, a value that is not a number; "nan" is kept as NaN for levelsFor to
/// reject by name).
std::map<std::string, double> parseValueList(const std::string& text);

}  // namespace vicc_glyphs::design
