#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "vicc_glyphs/bspline/fowler_bartels.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

// A long, gently curved spline with many uniform spans, so constraints act locally.
BSplineCurve longCurve() {
  std::vector<Point2> points;
  for (int i = 0; i < 20; ++i) points.emplace_back(5.0 * i, 3.0 * std::sin(0.4 * i));
  return BSplineCurve(3, BSplineCurve::clampedUniformKnots(3, 20, 0.0, 17.0), points);
}

TEST(FowlerBartelsTest, MovesTheCurveExactlyThroughAPositionAndLeavesFarPartsAlone) {
  const BSplineCurve curve = longCurve();
  const double u = 8.3;
  const Point2 target = curve.pointAt(u) + Point2(1.0, -4.0);
  const BSplineCurve moved = fowlerBartelsModify(curve, {{u, target, 0}});
  EXPECT_LT((moved.pointAt(u) - target).norm(), 1e-9);
  // Only the four de Boor points whose basis functions are non-zero at u move ...
  int changed = 0;
  for (int i = 0; i < curve.controlPointCount(); ++i) {
    changed += (moved.controlPoints()[i] - curve.controlPoints()[i]).norm() > 0.0;
  }
  EXPECT_EQ(changed, 4);
  // ... so the curve outside their support [5, 12] stays exactly where it was.
  for (double far : {0.0, 2.0, 4.9, 12.1, 15.0, 17.0}) {
    EXPECT_LT((moved.pointAt(far) - curve.pointAt(far)).norm(), 1e-12) << far;
  }
}

TEST(FowlerBartelsTest, OffsetsAreTheMinimumNormSolution) {
  // For one constraint, Eq. 2.48 gives Delta d_j = N_j(u) Delta p / sum_k N_k(u)^2.
  const BSplineCurve curve = longCurve();
  const double u = 3.7;
  const Point2 delta(0.5, 2.0);
  const BSplineCurve moved = fowlerBartelsModify(curve, {{u, curve.pointAt(u) + delta, 0}});
  const BasisRow row = curve.basisAt(u);
  const double norm2 = row.values.squaredNorm();
  for (int j = 0; j < row.values.size(); ++j) {
    const int i = row.first_index + j;
    const Point2 expected = row.values[j] / norm2 * delta;
    EXPECT_LT((moved.controlPoints()[i] - curve.controlPoints()[i] - expected).norm(), 1e-12);
  }
}

TEST(FowlerBartelsTest, SatisfiesSeveralPositionAndDerivativeConstraintsAtOnce) {
  const BSplineCurve curve = longCurve();
  const std::vector<CurveConstraint> constraints = {
      {2.5, Point2(12, 6), 0},
      {2.5, Point2(4, 0), 1},  // tangent there
      {9.0, Point2(45, -5), 0},
      {16.2, Point2(80, 1), 0},
  };
  const BSplineCurve moved = fowlerBartelsModify(curve, constraints);
  for (const CurveConstraint& c : constraints) {
    EXPECT_LT((moved.derivativeAt(c.parameter, c.derivative_order) - c.target).norm(), 1e-9)
        << c.parameter;
  }
  EXPECT_LT((moved.pointAt(6.0) - curve.pointAt(6.0)).norm(), 1e-12);  // between supports
}

TEST(FowlerBartelsTest, RejectsTooManyConstraintsAndBadInput) {
  const BSplineCurve curve = longCurve();
  // Five positions inside one knot span: only four de Boor points act there.
  std::vector<CurveConstraint> crowded;
  for (int i = 0; i < 5; ++i) crowded.push_back({8.1 + 0.15 * i, Point2(40 + i, 2), 0});
  EXPECT_THROW(fowlerBartelsModify(curve, crowded), std::invalid_argument);
  // The same point asked to be in two places.
  EXPECT_THROW(fowlerBartelsModify(curve, {{4.0, Point2(0, 0), 0}, {4.0, Point2(1, 0), 0}}),
               std::invalid_argument);
  EXPECT_THROW(fowlerBartelsModify(curve, {{18.0, Point2(0, 0), 0}}), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(fowlerBartelsModify(curve, {{nan, Point2(0, 0), 0}}), std::invalid_argument);
  EXPECT_THROW(fowlerBartelsModify(curve, {{4.0, Point2(nan, 0), 0}}), std::invalid_argument);
  EXPECT_THROW(fowlerBartelsModify(curve, {{4.0, Point2(0, 0), -1}}), std::invalid_argument);
  // No constraints: nothing changes.
  EXPECT_EQ(fowlerBartelsModify(curve, {}).controlPoints(), curve.controlPoints());
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
