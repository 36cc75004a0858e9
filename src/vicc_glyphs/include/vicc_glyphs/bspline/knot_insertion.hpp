#pragma once
// Knot insertion by Boehm's algorithm (thesis 2.5.2, Eq. 2.41): adds degrees of freedom without
// changing the curve's shape.

#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

/// Inserts the knot value `u` `times` times. Throws std::invalid_argument when u is not finite
/// or outside the domain, when times < 1, or when the result would exceed the allowed
/// multiplicity (degree inside the domain, degree + 1 at its ends).
BSplineCurve insertKnot(const BSplineCurve& curve, double u, int times = 1);

/// Inserts each value of `values` once (values may repeat to insert a knot several times).
BSplineCurve insertKnots(const BSplineCurve& curve, const std::vector<double>& values);

/// Raises every breakpoint inside the domain to at least multiplicity `target` (<= degree)
/// and both domain ends to at least `target`; target = degree gives the Bezier (piecewise
/// polynomial) form of thesis 2.5.2.
BSplineCurve raiseMultiplicities(const BSplineCurve& curve, int target);

}  // namespace bspline
}  // namespace vicc_glyphs
