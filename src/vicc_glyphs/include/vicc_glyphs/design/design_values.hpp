#pragma once
// "k=v,k=v" value lists of the design command line.

#include <map>
#include <optional>
#include <string>

namespace vicc_glyphs::design {

/// `text` as a decimal number (no blanks, no hexadecimal; "nan" and "inf" as such, a number
/// below the normal doubles as itself); empty when it is not one.
std::optional<double> parseDecimal(const std::string& text);

/// Parses "name=number,..." ; throws DesignValueError naming the bad entry (no '=', an empty
/// name, a repeated name, a value that is not a number; "nan" is kept as NaN for levelsFor to
/// reject by name).
std::map<std::string, double> parseValueList(const std::string& text);

}  // namespace vicc_glyphs::design
