#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "vicc_glyphs/bspline/bezier_conversion.hpp"
#include "vicc_glyphs/bspline/knot_insertion.hpp"
#include "vicc_glyphs/bspline/spline_diffusion_curve.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Two segments meeting in a corner (C0).
std::vector<Point2> cornerChain() {
  return {{0, 0}, {2, 3}, {4, 3}, {6, 0}, {7, 3}, {9, 4}, {11, 2}};
}

// Three segments with collinear handles of different lengths at both joins (C1).
std::vector<Point2> smoothChain() {
  return {{0, 0}, {1, 2}, {3, 3}, {5, 3}, {9, 3}, {11, 0}, {12, -2}, {12.5, -3}, {15, -4}, {17, 0}};
}

// Closed: four C1 quarter arcs of a circle plus a C0 corner where it closes.
std::vector<Point2> closedChain() {
  const double k = 0.5522847498 * 20.0;
  const Point2 c(30, 30);
  return {c + Point2(20, 0),   c + Point2(20, k),  c + Point2(k, 20),  c + Point2(0, 20),
          c + Point2(-k, 20),  c + Point2(-20, k), c + Point2(-20, 0), c + Point2(-20, -k),
          c + Point2(-k, -20), c + Point2(0, -20), c + Point2(k, -20), c + Point2(20, -k),
          c + Point2(20, 0)};
}

double maxPointDistance(const std::vector<Point2>& a, const std::vector<Point2>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    worst = std::max(worst, (a[i] - b[i]).norm());
  }
  return worst;
}

// Largest distance between the chain at s and the spline at the mapped parameter.
double maxGeometryDeviation(const std::vector<Point2>& chain, const SplineFromBezier& spline) {
  DiffusionCurve curve;
  curve.control_points = chain;
  double worst = 0.0;
  const int segments = curve.segmentCount();
  for (int i = 0; i <= 1000; ++i) {
    const double s = segments * i / 1000.0;
    const double u = spline.parameter_map.toSplineParameter(s);
    worst = std::max(worst, (curve.pointAt(s) - spline.curve.pointAt(u)).norm());
  }
  return worst;
}

TEST(BezierConversionTest, CornerJoinGetsATripleKnotAndRoundTrips) {
  const SplineFromBezier spline = bezierChainToBSpline(cornerChain());
  EXPECT_EQ(spline.smooth_joins, std::vector<bool>{false});
  EXPECT_EQ(spline.curve.controlPointCount(), 7);
  EXPECT_EQ(spline.curve.multiplicity(spline.parameter_map.breakpoints()[1]), 3);
  EXPECT_DOUBLE_EQ(spline.curve.domainBegin(), 0.0);
  EXPECT_DOUBLE_EQ(spline.curve.domainEnd(), 2.0);
  EXPECT_LT(maxGeometryDeviation(cornerChain(), spline), 1e-9);
  const BezierFromSpline back = bsplineToBezierChain(spline.curve);
  EXPECT_LT(maxPointDistance(back.control_points, cornerChain()), 1e-6);
}

TEST(BezierConversionTest, SmoothJoinsGetDoubleKnotsScaledIntervalsAndRoundTrip) {
  const std::vector<Point2> chain = smoothChain();
  const SplineFromBezier spline = bezierChainToBSpline(chain);
  EXPECT_EQ(spline.smooth_joins, (std::vector<bool>{true, true}));
  EXPECT_EQ(spline.curve.controlPointCount(), 10 - 2);  // both join points dropped
  const std::vector<double>& breaks = spline.parameter_map.breakpoints();
  ASSERT_EQ(breaks.size(), 4u);
  // Interval ratios follow the end-tangent lengths: 4/2 at the first join, 1/sqrt(5) at the
  // second; the domain is scaled to [0, K].
  EXPECT_NEAR((breaks[2] - breaks[1]) / (breaks[1] - breaks[0]), 2.0, 1e-12);
  EXPECT_NEAR((breaks[3] - breaks[2]) / (breaks[2] - breaks[1]), std::sqrt(1.25) / std::sqrt(5.0),
              1e-12);
  EXPECT_DOUBLE_EQ(breaks.back(), 3.0);
  for (int k = 1; k <= 2; ++k) {
    EXPECT_EQ(spline.curve.multiplicity(breaks[k]), 2);
    const Point2 left = spline.curve.derivativeAt(breaks[k] - 1e-12);
    const Point2 right = spline.curve.derivativeAt(breaks[k] + 1e-12);
    EXPECT_LT((left - right).norm(), 1e-6 * left.norm()) << "C1 at join " << k;
  }
  EXPECT_LT(maxGeometryDeviation(chain, spline), 1e-9);
  const BezierFromSpline back = bsplineToBezierChain(spline.curve);
  EXPECT_LT(maxPointDistance(back.control_points, chain), 1e-6);
}

TEST(BezierConversionTest, ClosedCurveRoundTripsAndStaysClosed) {
  const std::vector<Point2> chain = closedChain();
  const SplineFromBezier spline = bezierChainToBSpline(chain);
  EXPECT_EQ(spline.smooth_joins, (std::vector<bool>{true, true, true}));
  EXPECT_TRUE(spline.curve.isClosed(1e-12));
  EXPECT_LT(maxGeometryDeviation(chain, spline), 1e-9);
  const BezierFromSpline back = bsplineToBezierChain(spline.curve);
  EXPECT_LT(maxPointDistance(back.control_points, chain), 1e-6);
}

TEST(BezierConversionTest, SmallKinksBelowTheThresholdAreSmoothedAndLargerOnesKept) {
  // Outgoing handle turned by `degrees` against the incoming one (lengths 2 and 3).
  const auto kinked = [](double degrees) {
    const double a = degrees * kPi / 180.0;
    return std::vector<Point2>{
        {0, 0},  {2, 2}, {4, 0}, {6, 0}, Point2(6, 0) + 3.0 * Point2(std::cos(a), std::sin(a)),
        {11, 3}, {13, 0}};
  };
  const SplineFromBezier small = bezierChainToBSpline(kinked(2.0));
  EXPECT_EQ(small.smooth_joins, std::vector<bool>{true});
  // The join moves by 2 |a| |b| sin(angle / 2) / (|a| + |b|).
  const double expected_shift = 2.0 * 2.0 * 3.0 * std::sin(1.0 * kPi / 180.0) / 5.0;
  const Point2 join = small.curve.pointAt(small.parameter_map.breakpoints()[1]);
  EXPECT_NEAR((join - Point2(6, 0)).norm(), expected_shift, 1e-12);

  EXPECT_EQ(bezierChainToBSpline(kinked(5.0)).smooth_joins, std::vector<bool>{false});
  BezierConversionOptions strict;
  strict.c1_angle_degrees = 1.0;
  EXPECT_EQ(bezierChainToBSpline(kinked(2.0), strict).smooth_joins, std::vector<bool>{false});
  EXPECT_LT(
      maxPointDistance(bsplineToBezierChain(bezierChainToBSpline(kinked(5.0)).curve).control_points,
                       kinked(5.0)),
      1e-6);
}

TEST(BezierConversionTest, RetractedHandlesGiveACornerNotADivisionByZero) {
  const std::vector<Point2> chain = {{0, 0}, {1, 1}, {3, 0}, {3, 0}, {3, 0}, {5, 1}, {6, 0}};
  const SplineFromBezier spline = bezierChainToBSpline(chain);
  EXPECT_EQ(spline.smooth_joins, std::vector<bool>{false});
  EXPECT_LT(maxPointDistance(bsplineToBezierChain(spline.curve).control_points, chain), 1e-6);
}

TEST(BezierConversionTest, ParameterMapInvertsAndTracksInsertedKnots) {
  const std::vector<Point2> chain = smoothChain();
  const SplineFromBezier spline = bezierChainToBSpline(chain);
  for (double s : {0.0, 0.3, 1.0, 1.7, 2.5, 3.0}) {
    EXPECT_NEAR(spline.parameter_map.toCurveParameter(spline.parameter_map.toSplineParameter(s)), s,
                1e-12);
  }
  // A knot inside segment 1 splits it in the back-conversion; s moves accordingly but still
  // names the same point.
  const double u_split = spline.parameter_map.toSplineParameter(1.4);
  const BezierFromSpline back = bsplineToBezierChain(insertKnot(spline.curve, u_split));
  ASSERT_EQ(back.control_points.size(), 13u);
  DiffusionCurve original;
  original.control_points = chain;
  DiffusionCurve refined;
  refined.control_points = back.control_points;
  for (double s : {0.2, 1.2, 1.4, 1.9, 2.6}) {
    const double s_new =
        back.parameter_map.toCurveParameter(spline.parameter_map.toSplineParameter(s));
    EXPECT_LT((refined.pointAt(s_new) - original.pointAt(s)).norm(), 1e-9) << s;
  }
  EXPECT_THROW(ChainParameterMap({0.0, 0.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(ChainParameterMap({0.0}), std::invalid_argument);
}

TEST(BezierConversionTest, DiffusionCurveColoursSurviveTheRoundTrip) {
  DiffusionCurve curve;
  curve.control_points = smoothChain();
  curve.left_colors = {{0.0, Color(1, 0, 0)}, {1.5, Color(0, 1, 0)}, {3.0, Color(0, 0, 1)}};
  curve.right_colors = {{0.7, Color(0.2, 0.2, 0.2)}};
  curve.blur_points = {{2.2, 1.5}};
  curve.right_emits = false;

  const SplineDiffusionCurve spline = toSplineDiffusionCurve(curve);
  // Each colour point names the same place on the curve in both representations.
  ASSERT_EQ(spline.left_colors.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LT((spline.geometry.pointAt(spline.left_colors[i].position) -
               curve.pointAt(curve.left_colors[i].position))
                  .norm(),
              1e-9);
  }
  EXPECT_DOUBLE_EQ(spline.left_colors.back().position, spline.geometry.domainEnd());

  const DiffusionCurve back = toDiffusionCurve(spline);
  EXPECT_LT(maxPointDistance(back.control_points, curve.control_points), 1e-6);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(back.left_colors[i].position, curve.left_colors[i].position, 1e-12);
    EXPECT_EQ(back.left_colors[i].rgb, curve.left_colors[i].rgb);
  }
  EXPECT_NEAR(back.right_colors[0].position, 0.7, 1e-12);
  EXPECT_NEAR(back.blur_points[0].position, 2.2, 1e-12);
  EXPECT_DOUBLE_EQ(back.blur_points[0].sigma, 1.5);
  EXPECT_TRUE(back.left_emits);
  EXPECT_FALSE(back.right_emits);
  DiffusionCurveImage image;
  image.width = image.height = 64;
  image.curves = {back};
  EXPECT_EQ(validate(image), "");
}

// The span-by-span blossoms give the same Bezier points as raising every knot to multiplicity 3
// by Boehm insertion (thesis 2.5.2), for single, double and triple interior knots.
TEST(BezierConversionTest, SpanBlossomsEqualTheKnotInsertionForm) {
  const std::vector<double> knots{0, 0, 0, 0, 0.5, 1.2, 1.2, 2.0, 2.0, 2.0, 2.7, 3, 3, 3, 3};
  std::vector<Point2> points;
  for (std::size_t i = 0; i + 4 < knots.size(); ++i) {
    points.push_back(Point2(std::cos(1.3 * i) * (3 + i), std::sin(0.7 * i) * 5 - i));
  }
  const BSplineCurve curve(3, knots, points);
  const BezierFromSpline chain = bsplineToBezierChain(curve);
  const BSplineCurve raised = raiseMultiplicities(curve, 3);
  const std::vector<Point2>& expected = raised.controlPoints();
  ASSERT_EQ(chain.control_points.size(), expected.size());  // 5 segments: 16 points
  EXPECT_EQ(chain.control_points.size(), 16u);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_LT((chain.control_points[i] - expected[i]).norm(), 1e-12) << i;
  }
  for (double u : {0.0, 0.3, 1.2, 1.9, 2.95, 3.0}) {
    DiffusionCurve bezier;
    bezier.control_points = chain.control_points;
    EXPECT_LT((bezier.pointAt(chain.parameter_map.toCurveParameter(u)) - curve.pointAt(u)).norm(),
              1e-12)
        << u;
  }
}

TEST(BezierConversionTest, RejectsInvalidInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(bezierChainToBSpline({}), std::invalid_argument);
  EXPECT_THROW(bezierChainToBSpline({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}}),
               std::invalid_argument);
  EXPECT_THROW(bezierChainToBSpline({{0, 0}, {1, nan}, {2, 2}, {3, 3}}), std::invalid_argument);
  BezierConversionOptions bad;
  bad.c1_angle_degrees = 200.0;
  EXPECT_THROW(bezierChainToBSpline(cornerChain(), bad), std::invalid_argument);
  const BSplineCurve quadratic(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}});
  EXPECT_THROW(bsplineToBezierChain(quadratic), std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
