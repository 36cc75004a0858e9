#pragma once
// ELSPIA (He et al. 2015, thesis 2.5.3 and 6.2.3.3): least-squares progressive-iterative
// approximation with a stretching-energy term. Starting from a curve's de Boor points, each
// iteration takes a steepest-descent step on
//   L(D) = sum_i |s(u_i) - p_i|^2 + omega * int |s'(u)|^2 du,
// i.e. D <- D + mu * (N^T (P - N D) - omega * E D), with the collocation matrix N and the
// stretching Gram matrix E. Every step moves each de Boor point by a weighted sum of the
// residuals in its support (the "progressive" geometric update) pulled back by the energy term.

#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

struct ElspiaOptions {
  /// omega >= 0: weight of the stretching energy; 0 gives plain LSPIA (least squares).
  double energy_weight = 0.0;
  int max_iterations = 2000;
  /// Stop when no de Boor point moves by more than this in one iteration (pixels).
  double tolerance = 1e-10;
  /// Keep the first and last de Boor point fixed: with a clamped knot vector the curve keeps its
  /// end points, so a closed curve stays closed.
  bool keep_end_points = false;
  /// Step length mu; 0 chooses 2 / (lambda_min + lambda_max) of N^T N + omega E, the fastest
  /// fixed step for this quadratic loss.
  double step = 0.0;
};

struct ElspiaResult {
  BSplineCurve curve;
  int iterations = 0;
  bool converged = false;
  double loss = 0.0;  ///< L(D) of the result
};

/// Runs ELSPIA from `initial` (its degree and knots are kept) towards `points` at `parameters`.
/// Throws std::invalid_argument for mismatched or non-finite input, parameters outside the
/// domain, a negative weight or a non-positive iteration count.
ElspiaResult elspiaFit(const BSplineCurve& initial, const std::vector<Point2>& points,
                       const std::vector<double>& parameters, const ElspiaOptions& options = {});

/// Re-represents `original` on a new knot vector of the same degree and domain (thesis 6.2.3.3:
/// after the knots were shifted or inserted): samples `samples_per_span` points per new knot
/// span plus the ends, starts from the original evaluated at the Greville abscissae of the new
/// knots and runs elspiaFit.
ElspiaResult refitOnKnots(const BSplineCurve& original, std::vector<double> knots,
                          const ElspiaOptions& options = {}, int samples_per_span = 8);

}  // namespace bspline
}  // namespace vicc_glyphs
