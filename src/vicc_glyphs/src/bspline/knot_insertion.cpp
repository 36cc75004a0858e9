#include "vicc_glyphs/bspline/knot_insertion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {
namespace {

// One Boehm step (Eq. 2.41 with r = 1): the p - 1 de Boor points d_{l-p+1} .. d_{l-1} are
// replaced by p points on the control polygon; `span` is l with
// t_l <= u < t_{l+1} (or the last non-empty span when u is the domain end).
BSplineCurve insertOnce(const BSplineCurve& curve, double u) {
  const int p = curve.degree();
  const int span = curve.findSpan(u);
  const std::vector<double>& t = curve.knots();
  const std::vector<Point2>& d = curve.controlPoints();

  std::vector<Point2> points;
  points.reserve(d.size() + 1);
  for (int i = 0; i <= span - p; ++i) points.push_back(d[i]);
  for (int i = span - p + 1; i <= span; ++i) {
    const double alpha = (u - t[i]) / (t[i + p] - t[i]);
    points.push_back((1.0 - alpha) * d[i - 1] + alpha * d[i]);
  }
  for (std::size_t i = span; i < d.size(); ++i) points.push_back(d[i]);

  std::vector<double> knots(t.begin(), t.begin() + span + 1);
  knots.push_back(u);
  knots.insert(knots.end(), t.begin() + span + 1, t.end());
  return BSplineCurve(p, std::move(knots), std::move(points));
}

}  // namespace

BSplineCurve insertKnot(const BSplineCurve& curve, double u, int times) {
  if (!std::isfinite(u) || u < curve.domainBegin() || u > curve.domainEnd()) {
    throw std::invalid_argument("insertKnot: value " + std::to_string(u) +
                                " is not inside the domain");
  }
  if (times < 1) throw std::invalid_argument("insertKnot: times must be at least 1");
  const bool interior = u > curve.domainBegin() && u < curve.domainEnd();
  const int allowed = interior ? curve.degree() : curve.degree() + 1;
  if (curve.multiplicity(u) + times > allowed) {
    throw std::invalid_argument("insertKnot: knot " + std::to_string(u) + " would occur " +
                                std::to_string(curve.multiplicity(u) + times) + " times, at most " +
                                std::to_string(allowed) + " allowed");
  }
  BSplineCurve result = curve;
  for (int k = 0; k < times; ++k) result = insertOnce(result, u);
  return result;
}

BSplineCurve insertKnots(const BSplineCurve& curve, const std::vector<double>& values) {
  BSplineCurve result = curve;
  for (double u : values) result = insertKnot(result, u, 1);
  return result;
}

BSplineCurve raiseMultiplicities(const BSplineCurve& curve, int target) {
  if (target < 1 || target > curve.degree()) {
    throw std::invalid_argument("raiseMultiplicities: target must be in [1, degree]");
  }
  BSplineCurve result = curve;
  for (double u : curve.breakpoints()) {
    const int missing = target - result.multiplicity(u);
    if (missing > 0) result = insertKnot(result, u, missing);
  }
  return result;
}

}  // namespace bspline
}  // namespace vicc_glyphs
