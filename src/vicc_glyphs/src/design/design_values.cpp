#include "vicc_glyphs/design/design_values.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "vicc_glyphs/design/glyph_design.hpp"

namespace vicc_glyphs::design {

std::optional<double> parseDecimal(const std::string& text) {
  // strtod would also take leading blanks and hexadecimal ("0x55"), and std::stod refuses a
  // number too small for a normal double (1e-320) as if it were none.
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) ||
      text.find_first_of("xX") != std::string::npos) {
    return std::nullopt;
  }
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

std::map<std::string, double> parseValueList(const std::string& text) {
  std::map<std::string, double> values;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw DesignValueError("value '" + item + "' must be name=number");
    }
    const std::string name = item.substr(0, equals), number = item.substr(equals + 1);
    const std::optional<double> parsed = parseDecimal(number);
    if (!parsed) throw DesignValueError(name + " = '" + number + "' is not a number");
    const double value = *parsed;
    if (!values.emplace(name, value).second) throw DesignValueError(name + " is given twice");
  }
  if (values.empty()) throw DesignValueError("no values given");
  return values;
}

}  // namespace vicc_glyphs::design
