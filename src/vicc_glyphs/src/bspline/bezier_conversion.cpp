#include "vicc_glyphs/bspline/bezier_conversion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {
namespace {

constexpr int kCubic = 3;
constexpr double kPi = 3.14159265358979323846;

// The blossom f(u1, u2, u3) of the cubic polynomial piece on knot span `span`: de Boor's
// algorithm with a different argument per level (Ramshaw); f(a, a, b) etc. are Bezier points.
Point2 blossom(const BSplineCurve& curve, int span, const std::array<double, kCubic>& u) {
  const std::vector<double>& t = curve.knots();
  const std::vector<Point2>& d = curve.controlPoints();
  std::array<Point2, kCubic + 1> p;
  for (int j = 0; j <= kCubic; ++j) p[j] = d[span - kCubic + j];
  for (int r = 1; r <= kCubic; ++r) {
    for (int j = kCubic; j >= r; --j) {
      const int i = span - kCubic + j;
      const double alpha = (u[r - 1] - t[i]) / (t[i + kCubic + 1 - r] - t[i]);
      p[j] = (1.0 - alpha) * p[j - 1] + alpha * p[j];
    }
  }
  return p[kCubic];
}

double angleBetweenDegrees(const Point2& a, const Point2& b) {
  return std::atan2(std::abs(cross(a, b)), a.dot(b)) * 180.0 / kPi;
}

// Tangents shorter than this fraction of the chain's extent count as retracted handles: their
// direction is meaningless and a ratio with them would blow up the parameter intervals.
double degenerateLength(const std::vector<Point2>& points) {
  Point2 low = points.front();
  Point2 high = points.front();
  for (const Point2& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return 1e-9 * std::max((high - low).norm(), 1e-300);
}

}  // namespace

SplineFromBezier bezierChainToBSpline(const std::vector<Point2>& control_points,
                                      const BezierConversionOptions& options) {
  const int count = static_cast<int>(control_points.size());
  if (count < 4 || (count - 1) % 3 != 0) {
    throw std::invalid_argument("bezierChainToBSpline: need 3K+1 control points (K >= 1), got " +
                                std::to_string(count));
  }
  for (const Point2& p : control_points) {
    if (!p.allFinite()) throw std::invalid_argument("bezierChainToBSpline: point not finite");
  }
  if (!(options.c1_angle_degrees >= 0.0 && options.c1_angle_degrees < 180.0)) {
    throw std::invalid_argument("bezierChainToBSpline: C1 angle must be in [0, 180) degrees");
  }
  const std::vector<Point2>& p = control_points;
  const int segments = (count - 1) / 3;
  const double tiny = degenerateLength(p);

  std::vector<double> intervals(segments, 1.0);
  std::vector<bool> smooth(segments - 1, false);
  for (int k = 1; k < segments; ++k) {
    const Point2 incoming = p[3 * k] - p[3 * k - 1];
    const Point2 outgoing = p[3 * k + 1] - p[3 * k];
    const bool tangents = incoming.norm() > tiny && outgoing.norm() > tiny;
    smooth[k - 1] = tangents && angleBetweenDegrees(incoming, outgoing) < options.c1_angle_degrees;
    double ratio = 1.0;
    if (smooth[k - 1]) {
      ratio = outgoing.norm() / incoming.norm();
    } else {
      const double before = (p[3 * k] - p[3 * k - 3]).norm();
      const double after = (p[3 * k + 3] - p[3 * k]).norm();
      if (before > tiny && after > tiny) ratio = after / before;
    }
    intervals[k] = intervals[k - 1] * ratio;
  }
  const double scale = segments / std::accumulate(intervals.begin(), intervals.end(), 0.0);
  std::vector<double> breakpoints(segments + 1, 0.0);
  for (int k = 0; k < segments; ++k) breakpoints[k + 1] = breakpoints[k] + scale * intervals[k];
  breakpoints.back() = segments;  // exact end despite rounding

  std::vector<double> knots(kCubic + 1, 0.0);
  std::vector<Point2> points = {p[0]};
  for (int k = 0; k < segments; ++k) {
    points.push_back(p[3 * k + 1]);
    points.push_back(p[3 * k + 2]);
    const bool last = k == segments - 1;
    const bool drop_join = !last && smooth[k];
    if (!drop_join) points.push_back(p[3 * k + 3]);
    const int multiplicity = last ? kCubic + 1 : (drop_join ? 2 : kCubic);
    knots.insert(knots.end(), multiplicity, breakpoints[k + 1]);
  }
  return SplineFromBezier{BSplineCurve(kCubic, std::move(knots), std::move(points)),
                          ChainParameterMap(std::move(breakpoints)), std::move(smooth)};
}

BezierFromSpline bsplineToBezierChain(const BSplineCurve& curve) {
  if (curve.degree() != kCubic) {
    throw std::invalid_argument("bsplineToBezierChain: only cubic B-splines, got degree " +
                                std::to_string(curve.degree()));
  }
  // Span by span instead of raising every knot to multiplicity 3 by repeated insertion, which
  // copies the whole curve per inserted knot (quadratic: PACEMOD's rectangle waves have thousands
  // of knots). The result is the same: the Bezier points are blossoms of each span's polynomial.
  const std::vector<double>& t = curve.knots();
  const int end = curve.controlPointCount();
  std::vector<Point2> points;
  std::vector<double> breaks;
  for (int span = kCubic; span < end; ++span) {
    if (!(t[span + 1] > t[span])) continue;
    const double a = t[span], b = t[span + 1];
    if (points.empty()) {
      points.push_back(blossom(curve, span, {a, a, a}));
      breaks.push_back(a);
    }
    points.push_back(blossom(curve, span, {a, a, b}));
    points.push_back(blossom(curve, span, {a, b, b}));
    points.push_back(blossom(curve, span, {b, b, b}));
    breaks.push_back(b);
  }
  if (points.empty()) throw std::invalid_argument("bsplineToBezierChain: empty domain");
  return BezierFromSpline{std::move(points), ChainParameterMap(std::move(breaks))};
}

}  // namespace bspline
}  // namespace vicc_glyphs
