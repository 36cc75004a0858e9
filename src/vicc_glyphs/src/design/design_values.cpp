#include "vicc_glyphs/design/design_values.hpp"

#include <cmath>
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
    size_t used = 0;
    double value = NAN;
    try {
      value = std::stod(number, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != number.size()) {
      throw DesignValueError(name + " = '" + number + "' is not a number");
    }
    if (!values.emplace(name, value).second) throw DesignValueError(name + " is given twice");
  }
  if (values.empty()) throw DesignValueError("no values given");
  return values;
}

}  // namespace vicc_glyphs::design
