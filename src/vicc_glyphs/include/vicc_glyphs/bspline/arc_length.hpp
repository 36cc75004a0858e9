#pragma once
// Arc-length parametrisation l(u) (Eq. 2.44) and its inverse u(l) by a chord-length lookup table
// (Eq. 2.46, thesis 6.2.3.3): the curve is sampled densely, the polygon lengths are summed, and
// values in between are interpolated linearly.

#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

class ArcLengthTable {
 public:
  /// Samples `samples_per_span` (>= 1) equal parameter steps in every knot span. The chord
  /// length underestimates the arc by about (kappa h)^2 / 24 relatively per step of length h;
  /// the default keeps that far below 0.1 % for curves whose spans turn by up to ~90 degrees.
  explicit ArcLengthTable(const BSplineCurve& curve, int samples_per_span = 64);

  double totalLength() const { return lengths_.back(); }
  /// l(u): length from the domain start to u (u clamped to the domain).
  double lengthAt(double u) const;
  /// u(l): the parameter whose length from the start is l (l clamped to [0, total]).
  double parameterAt(double length) const;
  /// parameterAt for each of `lengths`, which must not decrease (std::invalid_argument
  /// otherwise): one walk over the table instead of a search per length.
  std::vector<double> parametersAt(const std::vector<double>& lengths) const;
  /// `count` >= 2 parameters equally spaced in arc length, from domain start to domain end.
  std::vector<double> equidistantParameters(int count) const;

  const std::vector<double>& parameters() const { return parameters_; }
  const std::vector<double>& lengths() const { return lengths_; }

 private:
  std::vector<double> parameters_;  ///< increasing sample parameters
  std::vector<double> lengths_;     ///< cumulative chord length at each sample
};

}  // namespace bspline
}  // namespace vicc_glyphs
