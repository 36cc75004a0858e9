#pragma once
// Conversion between the Bezier chains of a diffusion curve and cubic B-splines:
// pre-processing (thesis 6.2.3.2) and post-processing (thesis 6.2.3.4).

#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"
#include "vicc_glyphs/bspline/chain_parameter_map.hpp"

namespace vicc_glyphs {
namespace bspline {

struct BezierConversionOptions {
  /// A join becomes C1 (double knot, join point dropped) when the directions of the incoming
  /// and outgoing end tangents differ by less than this angle in degrees (thesis: 3.5).
  double c1_angle_degrees = 3.5;
};

/// A cubic B-spline made from a Bezier chain, with the map from the chain's curve parameter s.
struct SplineFromBezier {
  BSplineCurve curve;
  ChainParameterMap parameter_map;
  /// One entry per interior join (join k between segments k-1 and k at index k-1): true where
  /// the join was made C1.
  std::vector<bool> smooth_joins;
};

/// Bezier chain (3K+1 control points) to a clamped cubic B-spline over [0, K].
///
/// Segment k gets the parameter interval h_k. At a join whose end tangents a = p_3k - p_3k-1
/// and b = p_3k+1 - p_3k deviate by less than the angle threshold, h_k = h_{k-1} |b| / |a| so
/// that the B-spline's derivative is continuous, a double knot is appended and the join point is
/// dropped from the de Boor points: the spline passes through (h_k p_3k-1 + h_{k-1} p_3k+1) /
/// (h_{k-1} + h_k): p_3k itself when a and b are parallel, otherwise a point moved from it by
/// 2 |a| |b| sin(angle / 2) / (|a| + |b|) (the price of ignoring a small kink). Other joins keep a
/// triple knot and their point (C0); their interval follows the chord-length ratio of the two
/// segments, as the tangents impose nothing there. The intervals are scaled so the domain is [0,
/// K].
///
/// Throws std::invalid_argument for a point count that is not 3K+1 (K >= 1), non-finite
/// points or an angle outside [0, 180).
SplineFromBezier bezierChainToBSpline(const std::vector<Point2>& control_points,
                                      const BezierConversionOptions& options = {});

/// A Bezier chain and the map from the spline parameter it came from.
struct BezierFromSpline {
  std::vector<Point2> control_points;  ///< 3K+1 points
  ChainParameterMap parameter_map;     ///< breakpoints: the spline's distinct knots in its domain
};

/// Cubic B-spline to a Bezier chain by knot insertion until every breakpoint has multiplicity
/// 3: the de Boor points are then the Bezier control points, one segment per knot span.
/// Throws std::invalid_argument for a degree other than 3.
BezierFromSpline bsplineToBezierChain(const BSplineCurve& curve);

}  // namespace bspline
}  // namespace vicc_glyphs
