#pragma once
// The quadratic curve energies of thesis 2.5.3 (after [VW95]) used as fairness terms:
// stretching E_s = int |s'(u)|^2 du and bending E_b = int |s''(u)|^2 du over the domain.

#include <Eigen/SparseCore>

#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {

/// Gram matrix G with G_ij = int N_i^(order)(u) N_j^(order)(u) du for the basis of `basis`
/// (order 1: stretching, order 2: bending), so that the energy is sum over x and y of D^T G D.
/// Integrated exactly by Gauss-Legendre quadrature on each knot span.
Eigen::SparseMatrix<double> energyMatrix(const BSplineCurve& basis, int order);

/// int |s^(order)(u)|^2 du of the curve itself (order 1: stretching, 2: bending energy).
double curveEnergy(const BSplineCurve& curve, int order);

}  // namespace bspline
}  // namespace vicc_glyphs
