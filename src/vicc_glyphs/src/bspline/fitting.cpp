#include "vicc_glyphs/bspline/fitting.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseQR>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {
namespace {

void checkParameters(const BSplineCurve& basis, const std::vector<double>& parameters) {
  for (double u : parameters) {
    if (!std::isfinite(u) || u < basis.domainBegin() || u > basis.domainEnd()) {
      throw std::invalid_argument("fitting: parameter " + std::to_string(u) +
                                  " is outside the domain or not finite");
    }
  }
}

}  // namespace

Eigen::SparseMatrix<double> collocationMatrix(const BSplineCurve& basis,
                                              const std::vector<double>& parameters, int order) {
  checkParameters(basis, parameters);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(parameters.size() * (basis.degree() + 1));
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const BasisRow row = basis.basisAt(parameters[i], order);
    for (int j = 0; j < row.values.size(); ++j) {
      if (row.values[j] != 0.0) {
        entries.emplace_back(static_cast<int>(i), row.first_index + j, row.values[j]);
      }
    }
  }
  Eigen::SparseMatrix<double> n(static_cast<int>(parameters.size()), basis.controlPointCount());
  n.setFromTriplets(entries.begin(), entries.end());
  return n;
}

std::vector<double> chordLengthParameters(const std::vector<Point2>& points, double begin,
                                          double end) {
  if (points.size() < 2) throw std::invalid_argument("chordLengthParameters: need >= 2 points");
  if (!std::isfinite(begin) || !std::isfinite(end) || !(begin < end)) {
    throw std::invalid_argument("chordLengthParameters: need finite begin < end");
  }
  std::vector<double> cumulative(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (!points[i].allFinite() || !points[i - 1].allFinite()) {
      throw std::invalid_argument("chordLengthParameters: point not finite");
    }
    cumulative[i] = cumulative[i - 1] + (points[i] - points[i - 1]).norm();
  }
  const double total = cumulative.back();
  std::vector<double> parameters(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double w =
        total > 0.0 ? cumulative[i] / total : static_cast<double>(i) / (points.size() - 1);
    parameters[i] = (1.0 - w) * begin + w * end;
  }
  parameters.back() = end;
  return parameters;
}

CubicLeastSquares::CubicLeastSquares(const BSplineCurve& basis,
                                     const std::vector<double>& parameters)
    : control_count_(basis.controlPointCount()) {
  checkParameters(basis, parameters);
  rows_ = basis.cubicBasisAt(parameters);
  factor_.reset(control_count_, 3);
  for (const CubicBasisRow& row : rows_) {
    for (int a = 0; a < 4; ++a) {
      for (int b = a; b < 4; ++b) {
        factor_.lower(row.first_index + b, row.first_index + a) += row.values[a] * row.values[b];
      }
    }
  }
  factor_.factorise();
  if (factor_.raisedPivots() > 0) {
    throw std::invalid_argument("CubicLeastSquares: the " + std::to_string(parameters.size()) +
                                " parameters do not determine all " +
                                std::to_string(control_count_) +
                                " de Boor points; every basis function needs data in its support");
  }
}

Eigen::MatrixX2d CubicLeastSquares::solve(const Eigen::MatrixX2d& targets) const {
  if (targets.rows() != parameterCount()) {
    throw std::invalid_argument("CubicLeastSquares: " + std::to_string(targets.rows()) +
                                " targets for " + std::to_string(parameterCount()) + " parameters");
  }
  // N^T P, one coordinate per array (the banded solve works on contiguous values).
  std::vector<double> x(control_count_, 0.0), y(control_count_, 0.0);
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const CubicBasisRow& row = rows_[i];
    const double px = targets(static_cast<Eigen::Index>(i), 0);
    const double py = targets(static_cast<Eigen::Index>(i), 1);
    for (int a = 0; a < 4; ++a) {
      x[row.first_index + a] += row.values[a] * px;
      y[row.first_index + a] += row.values[a] * py;
    }
  }
  factor_.solve(x.data(), y.data());
  Eigen::MatrixX2d control(control_count_, 2);
  for (int j = 0; j < control_count_; ++j) control.row(j) << x[j], y[j];
  return control;
}

std::vector<Point2> CubicLeastSquares::solvePoints(const Eigen::MatrixX2d& targets) const {
  const Eigen::MatrixX2d control = solve(targets);
  std::vector<Point2> points(static_cast<std::size_t>(control.rows()));
  for (Eigen::Index i = 0; i < control.rows(); ++i) {
    points[static_cast<std::size_t>(i)] = control.row(i).transpose();
  }
  return points;
}

BSplineCurve leastSquaresFit(int degree, std::vector<double> knots,
                             const std::vector<Point2>& points,
                             const std::vector<double>& parameters) {
  if (points.empty() || points.size() != parameters.size()) {
    throw std::invalid_argument("leastSquaresFit: need as many parameters as points, at least 1");
  }
  for (const Point2& p : points) {
    if (!p.allFinite()) throw std::invalid_argument("leastSquaresFit: point not finite");
  }
  const int control_count = static_cast<int>(knots.size()) - degree - 1;
  // The basis curve validates degree and knots; its zero de Boor points are placeholders.
  BSplineCurve curve(degree, std::move(knots),
                     std::vector<Point2>(std::max(control_count, 0), Point2::Zero()));
  const Eigen::SparseMatrix<double> n = collocationMatrix(curve, parameters);
  Eigen::MatrixX2d targets(points.size(), 2);
  for (std::size_t i = 0; i < points.size(); ++i) targets.row(i) = points[i].transpose();

  Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr;
  qr.compute(n);
  if (qr.info() != Eigen::Success || qr.rank() < n.cols()) {
    throw std::invalid_argument("leastSquaresFit: the parameters do not determine all " +
                                std::to_string(n.cols()) + " de Boor points (rank " +
                                std::to_string(qr.rank()) +
                                "); every basis function needs data in its support");
  }
  const Eigen::MatrixX2d solution = qr.solve(targets);
  std::vector<Point2> control_points(solution.rows());
  for (int i = 0; i < solution.rows(); ++i) control_points[i] = solution.row(i).transpose();
  curve.setControlPoints(std::move(control_points));
  return curve;
}

}  // namespace bspline
}  // namespace vicc_glyphs
