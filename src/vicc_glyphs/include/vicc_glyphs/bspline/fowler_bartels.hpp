#pragma once
// Constraint-based direct curve manipulation after Fowler and Bartels 1993 (thesis Eq. 2.48,
// 6.2.3.3): the de Boor points move by the smallest offsets (least squares) for which the curve
// meets given positions (or derivatives) at given parameters exactly:
//   Delta D = N^T (N N^T)^{-1} Delta P.

#include <cstddef>
#include <vector>

#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

/// Requires s^(derivative_order)(parameter) == target after the modification.
struct CurveConstraint {
  double parameter = 0.0;
  Point2 target = Point2::Zero();
  int derivative_order = 0;  ///< 0: position, 1: first derivative d s / d u, ...
};

/// A constraint's row of N (the basis functions, or their derivatives of its order, at its
/// parameter) and the offset Delta P the curve has to move by there (the target minus the
/// curve's value, or its derivative of that order). Throws std::invalid_argument, naming `caller`
/// and the constraint's `index`, for a non-finite or out-of-domain parameter, a non-finite target
/// or a negative order. Shared by fowlerBartelsModify and PACEMOD's banded solve of the same
/// equations.
struct ConstraintRow {
  BasisRow basis;
  Point2 offset = Point2::Zero();
};
ConstraintRow constraintRow(const BSplineCurve& curve, const CurveConstraint& constraint,
                            std::size_t index, const char* caller);

/// Returns the modified curve (same degree and knots). Only de Boor points whose basis
/// functions are non-zero at some constraint move. Throws std::invalid_argument for non-finite
/// or out-of-domain constraints, a negative order, or when the constraints are contradictory or
/// outnumber the local degrees of freedom (rank of N below the constraint count): insert knots
/// near them first (thesis 6.2.3.3).
BSplineCurve fowlerBartelsModify(const BSplineCurve& curve,
                                 const std::vector<CurveConstraint>& constraints);

}  // namespace bspline
}  // namespace vicc_glyphs
