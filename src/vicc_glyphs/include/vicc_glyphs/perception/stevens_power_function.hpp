#pragma once
// Stevens's power law with an additive term (thesis 6.1.3.3): e(x) = a * x^b + c maps a
// stimulus magnitude x (adu) to the perceived magnitude (adu). The additive c compensates the
// adu scale's missing zero origin.

#include <string>

namespace vicc_glyphs::perception {

struct StevensPowerFunction {
  double a = 1.0;
  double b = 1.0;
  double c = 0.0;

  /// e(x); x must be > 0 (adu scales start at 1).
  double perceived(double stimulus_adu) const;
  /// e^-1(v) = ((v - c) / a)^(1/b). Throws std::domain_error when v is not reachable
  /// ((v - c) / a <= 0), since no stimulus produces that perception.
  double stimulusFor(double perceived_adu) const;
  /// Empty if valid, else the reason (a > 0, b > 0, all finite).
  std::string problem() const;
};

}  // namespace vicc_glyphs::perception
