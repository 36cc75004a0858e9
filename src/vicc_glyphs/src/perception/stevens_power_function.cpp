#include "vicc_glyphs/perception/stevens_power_function.hpp"

#include <cmath>
#include <stdexcept>

namespace vicc_glyphs::perception {

double StevensPowerFunction::perceived(double stimulus_adu) const {
  return a * std::pow(stimulus_adu, b) + c;
}

double StevensPowerFunction::stimulusFor(double perceived_adu) const {
  const double base = (perceived_adu - c) / a;
  if (!(base > 0.0)) {
    throw std::domain_error("perceived magnitude " + std::to_string(perceived_adu) +
                            " adu is below e(0) = c = " + std::to_string(c) +
                            ": no stimulus produces it");
  }
  return std::pow(base, 1.0 / b);
}

std::string StevensPowerFunction::problem() const {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return "a, b, c must be finite";
  if (!(a > 0.0)) return "a must be > 0 (perception must grow with the stimulus)";
  if (!(b > 0.0)) return "b must be > 0";
  return "";
}

}  // namespace vicc_glyphs::perception
