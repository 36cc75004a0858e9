#include "vicc_glyphs/bspline/fowler_bartels.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {

ConstraintRow constraintRow(const BSplineCurve& curve, const CurveConstraint& constraint,
                            std::size_t index, const char* caller) {
  const CurveConstraint& c = constraint;
  if (!std::isfinite(c.parameter) || c.parameter < curve.domainBegin() ||
      c.parameter > curve.domainEnd() || !c.target.allFinite() || c.derivative_order < 0) {
    throw std::invalid_argument(std::string(caller) + ": constraint " + std::to_string(index) +
                                " is not finite, outside the domain or has a negative order");
  }
  return {curve.basisAt(c.parameter, c.derivative_order),
          c.target - curve.derivativeAt(c.parameter, c.derivative_order)};
}

BSplineCurve fowlerBartelsModify(const BSplineCurve& curve,
                                 const std::vector<CurveConstraint>& constraints) {
  if (constraints.empty()) return curve;
  const int rows = static_cast<int>(constraints.size());
  Eigen::MatrixXd n = Eigen::MatrixXd::Zero(rows, curve.controlPointCount());
  Eigen::MatrixX2d offsets(rows, 2);
  for (int i = 0; i < rows; ++i) {
    const ConstraintRow row = constraintRow(curve, constraints[i], i, "fowlerBartelsModify");
    n.block(i, row.basis.first_index, 1, row.basis.values.size()) = row.basis.values.transpose();
    offsets.row(i) = row.offset.transpose();
  }
  Eigen::FullPivLU<Eigen::MatrixXd> rank_check(n);
  if (rank_check.rank() < rows) {
    throw std::invalid_argument(
        "fowlerBartelsModify: " + std::to_string(rows) + " constraints but only rank " +
        std::to_string(rank_check.rank()) +
        " (contradictory constraints or too few de Boor points nearby: insert knots)");
  }
  // Eq. 2.48: the minimum-norm offsets that satisfy N Delta D = Delta P.
  const Eigen::MatrixXd gram = n * n.transpose();
  const Eigen::MatrixX2d control_offsets = n.transpose() * gram.ldlt().solve(offsets);

  std::vector<Point2> points = curve.controlPoints();
  for (std::size_t j = 0; j < points.size(); ++j) {
    points[j] += control_offsets.row(static_cast<int>(j)).transpose();
  }
  BSplineCurve result = curve;
  result.setControlPoints(std::move(points));
  return result;
}

}  // namespace bspline
}  // namespace vicc_glyphs
