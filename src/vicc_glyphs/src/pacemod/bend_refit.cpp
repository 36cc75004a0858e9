#include "bend_refit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "vicc_glyphs/bspline/knot_insertion.hpp"

namespace vicc_glyphs {
namespace pacemod {
namespace detail {
namespace {

constexpr int kSamplesPerSpan = 4;
// Samples per knot point span for the first look at a window (is the curve off the path?).
constexpr int kProbesPerSpan = 4;
constexpr double kMinSpan = 1e-6;  // px: shorter knot spans carry no samples

using bspline::BasisRow;
using bspline::BSplineCurve;

// The de Boor points [first, last] of `curve` whose support (t_j, t_{j+p+1}) meets the open
// interval (begin, end).
struct FreePoints {
  int first = 0;
  int last = -1;
  int count() const { return last - first + 1; }
};

FreePoints pointsMeeting(const BSplineCurve& curve, double begin, double end) {
  const std::vector<double>& t = curve.knots();
  const int after_begin = static_cast<int>(std::upper_bound(t.begin(), t.end(), begin) - t.begin());
  const int from_end = static_cast<int>(std::lower_bound(t.begin(), t.end(), end) - t.begin());
  return {std::max(after_begin - curve.degree() - 1, 0),
          std::min(from_end - 1, curve.controlPointCount() - 1)};
}

// Sample parameters inside (begin, end]: kSamplesPerSpan per non-empty knot span of t.
std::vector<double> sampleParameters(const std::vector<double>& t, double begin, double end) {
  std::vector<double> at;
  auto knot = std::upper_bound(t.begin(), t.end(), begin);
  double a = begin;
  while (a < end) {
    const double b = knot == t.end() ? end : std::min(*knot, end);
    if (b - a > kMinSpan) {
      for (int k = 1; k <= kSamplesPerSpan; ++k) at.push_back(a + (b - a) * k / kSamplesPerSpan);
    }
    a = b;
    if (knot == t.end()) break;
    ++knot;
  }
  return at;
}

Point2 evaluate(const BasisRow& row, const std::vector<Point2>& points) {
  Point2 p = Point2::Zero();
  for (int k = 0; k < row.values.size(); ++k) p += row.values(k) * points[row.first_index + k];
  return p;
}

double largestDistance(const std::vector<BasisRow>& rows, const std::vector<Point2>& points,
                       const std::vector<Point2>& targets) {
  double largest = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    largest = std::max(largest, (evaluate(rows[i], points) - targets[i]).norm());
  }
  return largest;
}

// The free de Boor points' basis values in `row` and the fixed ones' part of the curve.
Point2 splitBasis(const BasisRow& basis, const FreePoints& free, const std::vector<Point2>& points,
                  Eigen::RowVectorXd& row) {
  row.setZero();
  Point2 fixed = Point2::Zero();
  for (int k = 0; k < basis.values.size(); ++k) {
    const int j = basis.first_index + k;
    if (j >= free.first && j <= free.last) {
      row(j - free.first) = basis.values(k);
    } else {
      fixed += basis.values(k) * points[j];
    }
  }
  return fixed;
}

// The least-squares de Boor points of `free` for the samples (their basis rows and targets),
// with the curve held at the `held` positions (a KKT system), written over `points`; false
// (nothing written) where it has no unique solution.
bool fitFreePoints(const FreePoints& free, const std::vector<BasisRow>& rows,
                   const std::vector<Point2>& targets,
                   const std::vector<std::pair<BasisRow, Point2>>& held,
                   std::vector<Point2>& points) {
  const int n = free.count(), m = static_cast<int>(held.size());
  if (static_cast<int>(rows.size()) < n) return false;
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(n + m, 2);
  Eigen::RowVectorXd row(n);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Point2 fixed = splitBasis(rows[i], free, points, row);
    kkt.topLeftCorner(n, n).noalias() += row.transpose() * row;
    rhs.topRows(n).noalias() += row.transpose() * (targets[i] - fixed).transpose();
  }
  for (int k = 0; k < m; ++k) {
    const Point2 fixed = splitBasis(held[k].first, free, points, row);
    kkt.block(n + k, 0, 1, n) = row;
    kkt.block(0, n + k, n, 1) = row.transpose();
    rhs.row(n + k) = (held[k].second - fixed).transpose();
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(kkt);
  if (lu.rank() < n + m) return false;
  const Eigen::MatrixX2d solution = lu.solve(rhs);
  if (!solution.allFinite()) return false;
  for (int j = 0; j < n; ++j) points[free.first + j] = solution.row(j).transpose();
  return true;
}

// Whether the curve leaves the path by more than `tolerance` between the window's ends.
bool strays(const BSplineCurve& curve, const BendWindow& window, const OffsetPath& path,
            double tolerance) {
  const std::vector<double>& p = window.knot_points;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (int k = 1; k < kProbesPerSpan; ++k) {
      const double l = p[i] + (p[i + 1] - p[i]) * k / kProbesPerSpan;
      if ((curve.pointAt(l) - path(l)).norm() > tolerance) return true;
    }
  }
  return false;
}

// The refit of one window on `points` (of `curve`, the curve with its knots inserted), kept
// where it is nearer the path over the stretch its free de Boor points reach.
void refitWindow(const BSplineCurve& curve, std::vector<Point2>& points, const BendWindow& window,
                 const std::vector<bspline::CurveConstraint>& pinned,
                 const std::vector<double>& keep_out, const OffsetPath& path) {
  const std::vector<double>& t = curve.knots();
  const int count = curve.controlPointCount();
  const FreePoints free =
      pointsMeeting(curve, window.knot_points.front(), window.knot_points.back());
  // The seam's constraints (the tangent at both ends) involve the two points at either end.
  if (free.count() <= 0 || free.first <= 1 || free.last + 2 >= count) return;
  const double begin = t[free.first], end = t[free.last + curve.degree() + 1];
  for (double l : keep_out) {
    if (l >= begin && l <= end) return;
  }
  std::vector<double> at = sampleParameters(t, begin, end);
  if (!at.empty()) at.pop_back();  // the end is outside every free point's support
  std::vector<BasisRow> rows;
  std::vector<Point2> targets;
  for (double l : at) {
    rows.push_back(curve.basisAt(l));
    targets.push_back(path(l));
  }
  std::vector<std::pair<BasisRow, Point2>> held;
  for (const bspline::CurveConstraint& c : pinned) {
    if (c.derivative_order == 0 && c.parameter > begin && c.parameter < end) {
      held.push_back({curve.basisAt(c.parameter), c.target});
    }
  }
  const std::vector<Point2> kept(points.begin() + free.first, points.begin() + free.last + 1);
  const double before = largestDistance(rows, points, targets);
  if (!fitFreePoints(free, rows, targets, held, points)) return;
  if (largestDistance(rows, points, targets) >= before) {
    std::copy(kept.begin(), kept.end(), points.begin() + free.first);
  }
}

}  // namespace

BSplineCurve refitBends(const BSplineCurve& curve, const std::vector<BendWindow>& windows,
                        const std::vector<bspline::CurveConstraint>& pinned,
                        const std::vector<double>& keep_out, const OffsetPath& path,
                        double tolerance) {
  std::vector<const BendWindow*> straying;
  std::vector<double> middles;
  for (const BendWindow& window : windows) {
    if (window.knot_points.size() < 3 || !strays(curve, window, path, tolerance)) continue;
    straying.push_back(&window);
    const std::vector<double>& p = window.knot_points;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
      const double middle = 0.5 * (p[i] + p[i + 1]);
      if (p[i + 1] - p[i] > 2.0 * kMinSpan && curve.multiplicity(middle) == 0) {
        middles.push_back(middle);
      }
    }
  }
  if (straying.empty()) return curve;
  std::sort(middles.begin(), middles.end());
  middles.erase(std::unique(middles.begin(), middles.end()), middles.end());
  BSplineCurve result = bspline::insertKnots(curve, middles);
  std::vector<Point2> points = result.controlPoints();
  for (const BendWindow* window : straying) {
    refitWindow(result, points, *window, pinned, keep_out, path);
  }
  result.setControlPoints(std::move(points));
  return result;
}

}  // namespace detail
}  // namespace pacemod
}  // namespace vicc_glyphs
