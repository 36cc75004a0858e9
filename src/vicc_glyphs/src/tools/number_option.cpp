#include "number_option.hpp"

#include <cmath>
#include <sstream>

#include "command_line.hpp"

namespace vicc_glyphs::tools {

double parseNumber(const std::string& option, const std::string& text, double minimum,
                   double maximum) {
  size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value) || value < minimum ||
      value > maximum) {
    std::ostringstream range;
    range << minimum << " to " << maximum;
    throw UsageError("option '--" + option + "' needs a number from " + range.str() + ", got '" +
                     text + "'");
  }
  return value;
}

}  // namespace vicc_glyphs::tools
