#include "vicc_glyphs/perception/stimulus_scale.hpp"

#include <algorithm>
#include <cmath>

namespace vicc_glyphs::perception {

double StimulusScale::physical(double adu_value) const {
  const double t = (adu_value - adu_min) / (adu_max - adu_min);
  return value_at_min + t * (value_at_max - value_at_min);
}

double StimulusScale::adu(double physical_value) const {
  const double t = (physical_value - value_at_min) / (value_at_max - value_at_min);
  return adu_min + t * (adu_max - adu_min);
}

double StimulusScale::physicalLow() const { return std::min(value_at_min, value_at_max); }
double StimulusScale::physicalHigh() const { return std::max(value_at_min, value_at_max); }

std::string StimulusScale::problem() const {
  for (double v : {adu_min, adu_max, value_at_min, value_at_max}) {
    if (!std::isfinite(v)) return "stimulus scale values must be finite";
  }
  if (!(adu_min > 0.0) || !(adu_min < adu_max)) return "needs 0 < adu min < adu max";
  if (!(value_at_min > 0.0) || !(value_at_max > 0.0) || value_at_min == value_at_max) {
    return "needs two distinct positive physical values";
  }
  return "";
}

}  // namespace vicc_glyphs::perception
