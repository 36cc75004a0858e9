#pragma once
// The experiment's mapping between a visual variable's stimulus value in arbitrary digital
// units (adu) and its physical value (Table 6.1): linear between two anchor points. For the
// frequencies the physical value is the period length, which falls as the adu rise.

#include <string>

namespace vicc_glyphs::perception {

struct StimulusScale {
  double adu_min = 1.0;       ///< adu of the first anchor (Table 6.1: 1)
  double adu_max = 12.0;      ///< adu of the second anchor
  double value_at_min = 0.0;  ///< physical value at adu_min (mm or V)
  double value_at_max = 1.0;  ///< physical value at adu_max

  /// Physical value (mm or V) of a stimulus in adu (linear, extrapolated outside the anchors).
  double physical(double adu) const;
  /// Inverse of physical().
  double adu(double physical_value) const;
  /// Smaller and larger physical end of the anchored range.
  double physicalLow() const;
  double physicalHigh() const;
  /// Empty if valid (finite, adu_min < adu_max, distinct values), else the reason.
  std::string problem() const;
};

}  // namespace vicc_glyphs::perception
