#include "vicc_glyphs/bspline/knot_insertion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vicc_glyphs {
namespace bspline {
namespace {

// A curve's knots and de Boor points refined in place: a splice cuts a wave of thousands of
// pieces at dozens of places, and a curve copied (and validated) per inserted knot made that
// quadratic in the wave's size.
class InPlaceRefinement {
 public:
  explicit InPlaceRefinement(const BSplineCurve& curve)
      : degree_(curve.degree()), knots_(curve.knots()), points_(curve.controlPoints()) {}

  // insertKnot's checks and `times` Boehm steps, on the refinement so far.
  void insert(double u, int times) {
    const double begin = knots_[degree_], end = knots_[points_.size()];
    if (!std::isfinite(u) || u < begin || u > end) {
      throw std::invalid_argument("insertKnot: value " + std::to_string(u) +
                                  " is not inside the domain");
    }
    if (times < 1) throw std::invalid_argument("insertKnot: times must be at least 1");
    const int allowed = u > begin && u < end ? degree_ : degree_ + 1;
    const auto range = std::equal_range(knots_.begin(), knots_.end(), u);
    const int multiplicity = static_cast<int>(range.second - range.first);
    if (multiplicity + times > allowed) {
      throw std::invalid_argument("insertKnot: knot " + std::to_string(u) + " would occur " +
                                  std::to_string(multiplicity + times) + " times, at most " +
                                  std::to_string(allowed) + " allowed");
    }
    for (int k = 0; k < times; ++k) insertOnce(u);
  }

  BSplineCurve curve() && { return BSplineCurve(degree_, std::move(knots_), std::move(points_)); }

 private:
  // One Boehm step (Eq. 2.41 with r = 1): the p - 1 de Boor points d_{l-p+1} .. d_{l-1} are
  // replaced by p points on the control polygon, l = spanOf(u).
  void insertOnce(double u) {
    const int p = degree_;
    const int span = knotSpan(knots_, static_cast<int>(points_.size()), u);
    replaced_.clear();
    for (int i = span - p + 1; i <= span; ++i) {
      const double alpha = (u - knots_[i]) / (knots_[i + p] - knots_[i]);
      replaced_.push_back((1.0 - alpha) * points_[i - 1] + alpha * points_[i]);
    }
    const Point2 moved = points_[span];
    points_.insert(points_.begin() + span, moved);  // d_l .. d_n move up by one
    std::copy(replaced_.begin(), replaced_.end(), points_.begin() + (span - p + 1));
    knots_.insert(knots_.begin() + span + 1, u);
  }

  int degree_;
  std::vector<double> knots_;
  std::vector<Point2> points_;
  std::vector<Point2> replaced_;
};

}  // namespace

BSplineCurve insertKnot(const BSplineCurve& curve, double u, int times) {
  InPlaceRefinement refinement(curve);
  refinement.insert(u, times);
  return std::move(refinement).curve();
}

BSplineCurve insertKnots(const BSplineCurve& curve, const std::vector<double>& values) {
  InPlaceRefinement refinement(curve);
  for (double u : values) refinement.insert(u, 1);
  return std::move(refinement).curve();
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
