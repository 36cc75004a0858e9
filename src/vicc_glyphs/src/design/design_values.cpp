#include "vicc_glyphs/design/design_values.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "vicc_glyphs/design/glyph_design.hpp"

namespace vicc_glyphs::design {

std::map<std::string, double> parseValueList(const std::string& text) {
  std::map<std::string, double> values;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    const size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw DesignValueError("value '" + item + "' must be name=number");
    }
    const std::string name = item.substr(0, equals), number = item.substr(equals + 1);
    // Decimal numbers only: strtod would also take leading blanks and hexadecimal ("0x55"),
    // and std::stod refuses a number too small for a normal double (1e-320) as if it were none.
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    const bool decimal = !number.empty() && !std::isspace(static_cast<unsigned char>(number[0])) &&
                         number.find_first_of("xX") == std::string::npos;
    if (!decimal || end != number.c_str() + number.size()) {
      throw DesignValueError(name + " = '" + number + "' is not a number");
    }
    if (!values.emplace(name, value).second) throw DesignValueError(name + " is given twice");
  }
  if (values.empty()) throw DesignValueError("no values given");
  return values;
}

}  // namespace vicc_glyphs::design
