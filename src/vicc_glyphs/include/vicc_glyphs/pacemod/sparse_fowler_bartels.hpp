#pragma once
// Fowler-Bartels (thesis Eq. 2.48) for the many local constraints of a wave: the same minimum-norm
// de Boor offsets Delta D = N^T (N N^T)^{-1} Delta P as bspline::fowlerBartelsModify, but with N
// sparse and the Gram matrix N N^T of the rows sorted along the curve factorised as a band
// (numerics::BandedCholesky), so the cost grows linearly with the number of constraints (the
// toolkit's dense version with its full-pivoting rank check grows with rows^2 * columns: seconds
// for a few hundred wave knot points).

#include <vector>

#include "vicc_glyphs/bspline/fowler_bartels.hpp"

namespace vicc_glyphs {
namespace pacemod {

/// Throws std::invalid_argument for out-of-domain or non-finite constraints, or when the Gram
/// matrix is singular (contradictory constraints or too few local de Boor points).
bspline::BSplineCurve sparseFowlerBartels(const bspline::BSplineCurve& curve,
                                          const std::vector<bspline::CurveConstraint>& constraints);

}  // namespace pacemod
}  // namespace vicc_glyphs
