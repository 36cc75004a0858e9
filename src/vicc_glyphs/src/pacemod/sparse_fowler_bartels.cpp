#include "vicc_glyphs/pacemod/sparse_fowler_bartels.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "vicc_glyphs/numerics/banded_cholesky.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace {

using bspline::ConstraintRow;

std::vector<ConstraintRow> constraintRows(
    const bspline::BSplineCurve& curve, const std::vector<bspline::CurveConstraint>& constraints) {
  std::vector<ConstraintRow> rows;
  rows.reserve(constraints.size());
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    rows.push_back(bspline::constraintRow(curve, constraints[i], i, "sparseFowlerBartels"));
  }
  return rows;
}

// The rows' order by the first de Boor point each touches: two rows meet in N N^T only when
// those are at most `degree` apart, so the Gram matrix of the rows in this order is banded
// (PACEMOD's seam and icon-corner rows come first and last, out of order along the curve).
std::vector<int> alongTheCurve(const std::vector<ConstraintRow>& rows) {
  std::vector<int> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return rows[a].basis.first_index < rows[b].basis.first_index;
  });
  return order;
}

// Entry (i, j) of N N^T: the sum over the de Boor points both rows touch.
double gramEntry(const bspline::BasisRow& a, const bspline::BasisRow& b) {
  const int shift = b.first_index - a.first_index;  // >= 0 for sorted rows a before b
  double sum = 0.0;
  for (int k = shift; k < a.values.size(); ++k) sum += a.values[k] * b.values[k - shift];
  return sum;
}

std::string contradictory(int count) {
  return "sparseFowlerBartels: " + std::to_string(count) +
         " constraints are contradictory or have too few de Boor points";
}

}  // namespace

bspline::BSplineCurve sparseFowlerBartels(
    const bspline::BSplineCurve& curve, const std::vector<bspline::CurveConstraint>& constraints) {
  if (constraints.empty()) return curve;
  const std::vector<ConstraintRow> unsorted = constraintRows(curve, constraints);
  const std::vector<int> order = alongTheCurve(unsorted);
  const auto row = [&](int i) -> const ConstraintRow& { return unsorted[order[i]]; };
  const int count = static_cast<int>(unsorted.size());
  const int degree = curve.degree();
  // Per row the first earlier row it meets; the widest such reach is the band.
  std::vector<int> first_met(count);
  int bandwidth = 0;
  for (int j = 0, i = 0; j < count; ++j) {
    while (row(i).basis.first_index + degree < row(j).basis.first_index) ++i;
    first_met[j] = i;
    bandwidth = std::max(bandwidth, j - i);
  }
  // More than 2 degree + 1 rows within such a reach share at most 2 degree + 1 de Boor points:
  // dependent, and a band that wide could be as large as the whole matrix.
  if (bandwidth > 2 * degree) throw std::invalid_argument(contradictory(count));
  numerics::BandedCholesky gram;
  gram.reset(count, bandwidth);
  double scale = 0.0;
  for (int j = 0; j < count; ++j) {
    for (int i = first_met[j]; i <= j; ++i) {
      gram.lower(j, i) = gramEntry(row(i).basis, row(j).basis);
    }
    scale = std::max(scale, gram.lower(j, j));
  }
  gram.factorise();
  if (gram.raisedPivots() > 0 || !(gram.smallestPivot() > 1e-12 * scale)) {
    throw std::invalid_argument(contradictory(count));
  }
  // Delta D = N^T (N N^T)^{-1} Delta P, per coordinate.
  std::vector<double> x(count), y(count);
  for (int i = 0; i < count; ++i) {
    x[i] = row(i).offset.x();
    y[i] = row(i).offset.y();
  }
  gram.solve(x.data(), y.data());
  std::vector<Point2> points = curve.controlPoints();
  for (int i = 0; i < count; ++i) {
    const bspline::BasisRow& basis = row(i).basis;
    for (int k = 0; k < basis.values.size(); ++k) {
      points[basis.first_index + k] += basis.values[k] * Point2(x[i], y[i]);
    }
  }
  bspline::BSplineCurve result = curve;
  result.setControlPoints(std::move(points));
  return result;
}

}  // namespace pacemod
}  // namespace vicc_glyphs
