#pragma once
// The piecewise-linear correspondence between the curve parameter s in [0, K] of a Bezier chain
// (diffusion_curve.hpp) and the parameter u of a B-spline with the same geometry: Bezier segment
// k covers the spline interval [breakpoints[k], breakpoints[k+1]] and its local parameter maps
// linearly onto it. Used to carry colour and blur points between the representations
// (thesis 6.2.3.2 and 6.2.3.4).

#include <vector>

namespace vicc_glyphs {
namespace bspline {

class ChainParameterMap {
 public:
  /// `breakpoints` are K + 1 strictly increasing finite spline parameters (K >= 1); throws
  /// std::invalid_argument otherwise.
  explicit ChainParameterMap(std::vector<double> breakpoints);

  int segmentCount() const { return static_cast<int>(breakpoints_.size()) - 1; }
  const std::vector<double>& breakpoints() const { return breakpoints_; }

  /// s in [0, K] (clamped) to the spline parameter u.
  double toSplineParameter(double s) const;
  /// Spline parameter u (clamped to the breakpoints' range) to s in [0, K].
  double toCurveParameter(double u) const;

 private:
  std::vector<double> breakpoints_;
};

}  // namespace bspline
}  // namespace vicc_glyphs
