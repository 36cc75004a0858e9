#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "vicc_glyphs/bspline/bezier_conversion.hpp"
#include "vicc_glyphs/bspline/bspline_curve.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

// A cubic with non-uniform interior knots, one of them double.
BSplineCurve wavyCurve() {
  return BSplineCurve(3, {0, 0, 0, 0, 0.7, 1.5, 1.5, 2.6, 4, 4, 4, 4},
                      {{0, 0}, {1, 3}, {3, 4}, {5, 1}, {6, -2}, {8, 0}, {9, 4}, {12, 3}});
}

TEST(BSplineCurveTest, SpanSamplesArePointAtOfEachPieceInOrder) {
  const BSplineCurve curve = wavyCurve();  // pieces [0, 0.7], [0.7, 1.5], [1.5, 2.6], [2.6, 4]
  std::vector<double> parameters;
  const std::vector<Point2> points = curve.sampleSpans(3, parameters);
  const std::vector<double> expected = {
      0,   0.7 / 3,       1.4 / 3,       0.7, 0.7 + 0.8 / 3, 0.7 + 1.6 / 3,
      1.5, 1.5 + 1.1 / 3, 1.5 + 2.2 / 3, 2.6, 2.6 + 1.4 / 3, 2.6 + 2.8 / 3,
      4};
  ASSERT_EQ(parameters.size(), expected.size());
  ASSERT_EQ(points.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(parameters[i], expected[i], 1e-12) << i;
    EXPECT_EQ(points[i], curve.pointAt(parameters[i])) << i;  // the same arithmetic
  }
  EXPECT_THROW(curve.sampleSpans(0, parameters), std::invalid_argument);
  // Many per piece: its Bezier form, the same points up to round-off.
  const std::vector<Point2> dense = curve.sampleSpans(16, parameters);
  ASSERT_EQ(parameters.size(), 4u * 16u + 1u);
  ASSERT_EQ(dense.size(), parameters.size());
  for (size_t i = 0; i < dense.size(); ++i) {
    EXPECT_NEAR((dense[i] - curve.pointAt(parameters[i])).norm(), 0.0, 1e-12) << i;
  }
  EXPECT_NEAR(parameters[16 + 5], 0.7 + 0.8 * 5 / 16, 1e-12);
}

// The polygon check searches a wave's spline flattened by flattenSpans; the renderer draws the
// Bezier chain it becomes, flattened by flattenCurve. Both must be the same polyline, also at a
// corner where the curve folds back (16 pieces on both sides of it).
TEST(BSplineCurveTest, FlattenedSpansAreTheFlattenedBezierChain) {
  const BSplineCurve curve(
      3, {0, 0, 0, 0, 1, 2, 2, 2, 3, 4, 4, 4, 4},
      {{0, 0}, {4, 1}, {8, 3}, {10, 6}, {10.2, 6.1}, {9, 5}, {6, 6}, {3, 9}, {0, 8}});
  ASSERT_EQ(curve.multiplicity(2), 3);  // a corner at u = 2, where the curve turns back
  std::vector<double> parameters;
  const std::vector<Point2> spans = curve.flattenSpans(parameters);
  DiffusionCurve chain;
  chain.control_points = bsplineToBezierChain(curve).control_points;
  std::vector<double> positions;
  const std::vector<Point2> drawn = flattenCurve(chain, &positions);
  ASSERT_EQ(chain.segmentCount(), 4);
  EXPECT_TRUE(segmentBesideFold(chain, 1));
  EXPECT_TRUE(segmentBesideFold(chain, 2));
  ASSERT_EQ(spans.size(), drawn.size());
  for (std::size_t i = 0; i < spans.size(); ++i) {
    EXPECT_LT((spans[i] - drawn[i]).norm(), 1e-9) << i;
    EXPECT_NEAR(parameters[i], positions[i], 1e-12) << i;  // one unit of u per segment here
  }
  EXPECT_THROW(
      BSplineCurve(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}}).flattenSpans(parameters),
      std::invalid_argument);
}

TEST(BSplineCurveTest, PointsOfSortedParametersArePointAtOfEach) {
  const BSplineCurve curve = wavyCurve();
  // Outside the domain, the knots themselves (one of them double), ties and the end.
  const std::vector<double> parameters = {-1.0,      0.0, 0.3, 0.7,      0.7, 1.1, 1.5,
                                          1.5000001, 2.6, 3.2, 3.999999, 4.0, 4.0, 5.0};
  const std::vector<Point2> points = curve.pointsAt(parameters);
  ASSERT_EQ(points.size(), parameters.size());
  for (size_t i = 0; i < parameters.size(); ++i) {
    // A span with several parameters is evaluated in Bezier form: the same up to round-off.
    EXPECT_LT((points[i] - curve.pointAt(parameters[i])).norm(), 1e-12) << i;
  }
  EXPECT_EQ(curve.pointsAt({3.2})[0], curve.pointAt(3.2));  // starts in a later span
  // Dozens per span (as OffsetFit samples a contour), spans' ends and the domain's end included.
  std::vector<double> dense;
  for (int k = 0; k <= 400; ++k) dense.push_back(curve.domainBegin() + k * 0.01);
  const std::vector<Point2> dense_points = curve.pointsAt(dense);
  ASSERT_EQ(dense_points.size(), dense.size());
  for (size_t i = 0; i < dense.size(); ++i) {
    EXPECT_LT((dense_points[i] - curve.pointAt(dense[i])).norm(), 1e-12) << dense[i];
  }
  EXPECT_THROW(curve.pointsAt({1.0, 0.5}), std::invalid_argument);
  EXPECT_THROW(curve.pointsAt({std::numeric_limits<double>::quiet_NaN()}), std::invalid_argument);
}

TEST(BSplineCurveTest, CubicBasisRowsOfSortedParametersAreBasisAtOfEach) {
  const BSplineCurve curve = wavyCurve();
  const std::vector<double> parameters = {0.0, 0.3, 0.7, 0.7, 1.5, 2.0, 3.999999, 4.0, 4.0};
  const std::vector<CubicBasisRow> rows = curve.cubicBasisAt(parameters);
  ASSERT_EQ(rows.size(), parameters.size());
  for (size_t i = 0; i < parameters.size(); ++i) {
    const BasisRow expected = curve.basisAt(parameters[i]);
    EXPECT_EQ(rows[i].first_index, expected.first_index) << i;
    for (int j = 0; j < 4; ++j) EXPECT_EQ(rows[i].values[j], expected.values[j]) << i << j;
  }
  EXPECT_THROW(curve.cubicBasisAt({2.0, 1.0}), std::invalid_argument);
  const BSplineCurve quadratic(2, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 0}});
  EXPECT_THROW(quadratic.cubicBasisAt({0.5}), std::invalid_argument);
}

TEST(BSplineCurveTest, SingleSpanClampedCubicIsTheBezierCurve) {
  DiffusionCurve bezier;
  bezier.control_points = {{0, 0}, {1, 2}, {3, 3}, {4, 0}};
  const BSplineCurve spline(3, {0, 0, 0, 0, 1, 1, 1, 1}, bezier.control_points);
  for (double u : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    EXPECT_LT((spline.pointAt(u) - bezier.pointAt(u)).norm(), 1e-12) << u;
    EXPECT_LT((spline.derivativeAt(u, 1) - bezier.derivativeAt(u)).norm(), 1e-12) << u;
  }
}

TEST(BSplineCurveTest, BasisFunctionsFormAPartitionOfUnity) {
  const BSplineCurve curve = wavyCurve();
  for (double u = 0.0; u <= 4.0; u += 0.05) {
    const BasisRow row = curve.basisAt(u);
    EXPECT_NEAR(row.values.sum(), 1.0, 1e-12) << u;
    EXPECT_GE(row.values.minCoeff(), -1e-15) << u;
    EXPECT_NEAR(curve.basisAt(u, 1).values.sum(), 0.0, 1e-10) << u;
    Point2 combined = Point2::Zero();
    for (int j = 0; j < row.values.size(); ++j) {
      combined += row.values[j] * curve.controlPoints()[row.first_index + j];
    }
    EXPECT_LT((combined - curve.pointAt(u)).norm(), 1e-12) << u;
  }
}

TEST(BSplineCurveTest, DerivativesMatchFiniteDifferences) {
  const BSplineCurve curve = wavyCurve();
  const double h = 1e-5;
  // Away from the knots, where the curve is polynomial on both sides of u +- h.
  for (double u : {0.3, 1.1, 2.0, 3.3, 3.9}) {
    const Point2 first = (curve.pointAt(u + h) - curve.pointAt(u - h)) / (2 * h);
    const Point2 second =
        (curve.pointAt(u + h) - 2.0 * curve.pointAt(u) + curve.pointAt(u - h)) / (h * h);
    const Point2 third = (curve.derivativeAt(u + h, 2) - curve.derivativeAt(u - h, 2)) / (2 * h);
    EXPECT_LT((curve.derivativeAt(u, 1) - first).norm(), 1e-6) << u;
    EXPECT_LT((curve.derivativeAt(u, 2) - second).norm(), 1e-3) << u;
    EXPECT_LT((curve.derivativeAt(u, 3) - third).norm(), 1e-5) << u;
  }
  EXPECT_EQ(curve.derivativeAt(1.0, 4), Point2::Zero());
}

TEST(BSplineCurveTest, DoubleKnotKeepsTheCurveC1ButNotC2) {
  const BSplineCurve curve = wavyCurve();
  const double eps = 1e-9;
  EXPECT_LT((curve.derivativeAt(1.5 - eps) - curve.derivativeAt(1.5 + eps)).norm(), 1e-6);
  EXPECT_GT((curve.derivativeAt(1.5 - eps, 2) - curve.derivativeAt(1.5 + eps, 2)).norm(), 1e-2);
}

TEST(BSplineCurveTest, EndsAndSpansOfAClampedCurve) {
  const BSplineCurve curve = wavyCurve();
  EXPECT_LT((curve.pointAt(0.0) - Point2(0, 0)).norm(), 1e-12);
  EXPECT_LT((curve.pointAt(4.0) - Point2(12, 3)).norm(), 1e-12);
  EXPECT_LT((curve.pointAt(7.0) - Point2(12, 3)).norm(), 1e-12);  // clamped to the domain
  EXPECT_EQ(curve.findSpan(0.0), 3);
  EXPECT_EQ(curve.findSpan(1.5), 6);
  EXPECT_EQ(curve.findSpan(4.0), 7);
  EXPECT_EQ(curve.multiplicity(1.5), 2);
  EXPECT_EQ(curve.breakpoints(), (std::vector<double>{0, 0.7, 1.5, 2.6, 4}));
  EXPECT_FALSE(curve.isClosed());
  EXPECT_EQ(curve.sample(5).size(), 5u);
}

TEST(BSplineCurveTest, ClampedUniformKnots) {
  EXPECT_EQ(BSplineCurve::clampedUniformKnots(3, 6, 0.0, 3.0),
            (std::vector<double>{0, 0, 0, 0, 1, 2, 3, 3, 3, 3}));
  EXPECT_THROW(BSplineCurve::clampedUniformKnots(3, 3, 0.0, 1.0), std::invalid_argument);
}

// Expects construction to throw std::invalid_argument whose message contains `fragment`.
void expectRejected(int degree, std::vector<double> knots, std::vector<Point2> points,
                    const std::string& fragment) {
  try {
    BSplineCurve(degree, std::move(knots), std::move(points));
    FAIL() << "expected std::invalid_argument mentioning '" << fragment << "'";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos) << error.what();
  }
}

TEST(BSplineCurveTest, RejectsInvalidInputWithAReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point2> four = {{0, 0}, {1, 1}, {2, 1}, {3, 0}};
  const std::vector<double> clamped = {0, 0, 0, 0, 1, 1, 1, 1};
  expectRejected(0, clamped, four, "degree");
  expectRejected(3, clamped, {}, "at least 4");
  expectRejected(3, {0, 0, 0, 1, 1, 1}, {{0, 0}, {1, 1}}, "at least 4");
  expectRejected(3, {0, 0, 0, 0, 1, 1, 1}, four, "expected 8 knots");
  expectRejected(3, {0, 0, 0, 0, 1, 0.5, 1, 1}, four, "decrease");
  expectRejected(3, {0, 0, 0, 0, nan, 1, 1, 1}, four, "not finite");
  expectRejected(3, clamped, {{0, 0}, {nan, 1}, {2, 1}, {3, 0}}, "not finite");
  expectRejected(3, {0, 0, 0, 0, 0, 0, 0, 0}, four, "empty domain");
  expectRejected(3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1},
                 {{0, 0}, {1, 1}, {2, 1}, {3, 0}, {4, 0}, {5, 1}, {6, 1}, {7, 0}}, "at most 3");
  expectRejected(3, {0, 0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, 1}, {2, 1}, {3, 0}, {4, 0}},
                 "at most 4");

  BSplineCurve curve(3, clamped, four);
  EXPECT_THROW(curve.pointAt(nan), std::invalid_argument);
  EXPECT_THROW(curve.derivativeAt(0.5, -1), std::invalid_argument);
  EXPECT_THROW(curve.setControlPoints({{0, 0}}), std::invalid_argument);
  EXPECT_EQ(curve.controlPointCount(), 4);  // unchanged after the failed update
  EXPECT_THROW(curve.sample(1), std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
