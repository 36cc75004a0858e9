#include "vicc_glyphs/pacemod/sparse_fowler_bartels.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace pacemod {

bspline::BSplineCurve sparseFowlerBartels(
    const bspline::BSplineCurve& curve, const std::vector<bspline::CurveConstraint>& constraints) {
  if (constraints.empty()) return curve;
  const int rows = static_cast<int>(constraints.size());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d offsets(rows, 2);
  for (int i = 0; i < rows; ++i) {
    const bspline::CurveConstraint& c = constraints[i];
    if (!std::isfinite(c.parameter) || c.parameter < curve.domainBegin() ||
        c.parameter > curve.domainEnd() || !c.target.allFinite() || c.derivative_order < 0) {
      throw std::invalid_argument("sparseFowlerBartels: constraint " + std::to_string(i) +
                                  " is not finite, outside the domain or has a negative order");
    }
    const bspline::BasisRow row = curve.basisAt(c.parameter, c.derivative_order);
    for (int k = 0; k < row.values.size(); ++k) {
      if (row.values[k] != 0.0) entries.emplace_back(i, row.first_index + k, row.values[k]);
    }
    offsets.row(i) = (c.target - curve.derivativeAt(c.parameter, c.derivative_order)).transpose();
  }
  Eigen::SparseMatrix<double> n(rows, curve.controlPointCount());
  n.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> gram = n * n.transpose();
  // PACEMOD's constraints are the knot points in order along the curve plus a few (the seam,
  // icon corners): the Gram matrix is banded but for those rows, and in the given order the
  // factor fills one column per such row. AMD's ordering cost more than it saved (the brain
  // with rectangle waves 12/10 mm, 1.2 mm: 33.2 -> 27.2 M instructions in this function).
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
      solver(gram);
  const double scale = gram.diagonal().maxCoeff();
  if (solver.info() != Eigen::Success ||
      !(solver.vectorD().cwiseAbs().minCoeff() > 1e-12 * scale)) {
    throw std::invalid_argument("sparseFowlerBartels: " + std::to_string(rows) +
                                " constraints are contradictory or have too few de Boor points");
  }
  const Eigen::MatrixX2d control_offsets = n.transpose() * solver.solve(offsets);
  std::vector<Point2> points = curve.controlPoints();
  for (std::size_t j = 0; j < points.size(); ++j) {
    points[j] += control_offsets.row(static_cast<int>(j)).transpose();
  }
  bspline::BSplineCurve result = curve;
  result.setControlPoints(std::move(points));
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
