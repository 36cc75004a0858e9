#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "vicc_glyphs/bspline/fitting.hpp"

namespace vicc_glyphs {
namespace bspline {
namespace {

BSplineCurve knownCurve() {
  return BSplineCurve(3, {0, 0, 0, 0, 0.8, 1.3, 2.1, 3, 3, 3, 3},
                      {{0, 0}, {2, 5}, {4, -1}, {6, 4}, {8, 0}, {10, 3}, {11, 1}});
}

TEST(FittingTest, LeastSquaresRecoversAKnownSplineFromItsSamples) {
  const BSplineCurve truth = knownCurve();
  std::vector<double> parameters;
  std::vector<Point2> points;
  for (int i = 0; i <= 200; ++i) {
    parameters.push_back(3.0 * i / 200.0);
    points.push_back(truth.pointAt(parameters.back()));
  }
  const BSplineCurve fit = leastSquaresFit(3, truth.knots(), points, parameters);
  ASSERT_EQ(fit.controlPointCount(), truth.controlPointCount());
  for (int i = 0; i < fit.controlPointCount(); ++i) {
    EXPECT_LT((fit.controlPoints()[i] - truth.controlPoints()[i]).norm(), 1e-9) << i;
  }
}

TEST(FittingTest, LeastSquaresMinimisesTheResidualOfNoisyData) {
  const BSplineCurve truth = knownCurve();
  std::vector<double> parameters;
  std::vector<Point2> points;
  for (int i = 0; i <= 100; ++i) {
    parameters.push_back(3.0 * i / 100.0);
    const double noise = 0.05 * std::sin(37.0 * i);  // deterministic "noise"
    points.push_back(truth.pointAt(parameters.back()) + Point2(noise, -noise));
  }
  const BSplineCurve fit = leastSquaresFit(3, truth.knots(), points, parameters);
  const auto residual = [&](const BSplineCurve& c) {
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      sum += (c.pointAt(parameters[i]) - points[i]).squaredNorm();
    }
    return sum;
  };
  // Optimal: moving any de Boor point a little only increases the residual.
  const double best = residual(fit);
  for (int j = 0; j < fit.controlPointCount(); ++j) {
    for (const Point2& step : {Point2(1e-3, 0), Point2(0, -1e-3)}) {
      std::vector<Point2> moved = fit.controlPoints();
      moved[j] += step;
      BSplineCurve other = fit;
      other.setControlPoints(moved);
      EXPECT_GT(residual(other), best) << j;
    }
  }
  EXPECT_LT(best, residual(truth));
}

TEST(FittingTest, InterpolatesWhenPointsEqualDeBoorPoints) {
  const std::vector<Point2> points = {{0, 0}, {1, 2}, {3, 3}, {4, 1}, {6, 2}, {7, 0}};
  const std::vector<double> parameters = chordLengthParameters(points, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(parameters.front(), 0.0);
  EXPECT_DOUBLE_EQ(parameters.back(), 1.0);
  // Interior knots by averaging the parameters keeps the Schoenberg-Whitney condition.
  std::vector<double> knots = {0, 0, 0, 0};
  for (int j = 1; j <= 2; ++j) {
    knots.push_back((parameters[j] + parameters[j + 1] + parameters[j + 2]) / 3.0);
  }
  knots.insert(knots.end(), 4, 1.0);
  const BSplineCurve fit = leastSquaresFit(3, knots, points, parameters);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_LT((fit.pointAt(parameters[i]) - points[i]).norm(), 1e-9) << i;
  }
}

TEST(FittingTest, CollocationMatrixRowsAreBasisValues) {
  const BSplineCurve basis = knownCurve();
  const Eigen::SparseMatrix<double> n = collocationMatrix(basis, {0.0, 1.0, 3.0});
  EXPECT_EQ(n.rows(), 3);
  EXPECT_EQ(n.cols(), 7);
  EXPECT_NEAR(n.coeff(0, 0), 1.0, 1e-15);
  EXPECT_NEAR(n.coeff(2, 6), 1.0, 1e-15);
  EXPECT_NEAR(Eigen::MatrixXd(n).row(1).sum(), 1.0, 1e-12);
}

TEST(FittingTest, BandedNormalEquationsGiveTheQrMinimiser) {
  const BSplineCurve truth = knownCurve();  // a double knot span and uneven spans
  std::vector<double> parameters;
  Eigen::MatrixX2d targets(121, 2);
  std::vector<Point2> points;
  for (int i = 0; i <= 120; ++i) {
    parameters.push_back(3.0 * i / 120.0);
    const double noise = 0.05 * std::sin(37.0 * i);
    points.push_back(truth.pointAt(parameters.back()) + Point2(noise, 2.0 * noise));
    targets.row(i) = points.back().transpose();
  }
  const CubicLeastSquares solver(truth, parameters);
  const BSplineCurve reference = leastSquaresFit(3, truth.knots(), points, parameters);
  const Eigen::MatrixX2d control = solver.solve(targets);
  ASSERT_EQ(control.rows(), truth.controlPointCount());
  for (int i = 0; i < control.rows(); ++i) {
    EXPECT_LT((control.row(i).transpose() - reference.controlPoints()[i]).norm(), 1e-9) << i;
  }
  // The rows are the basis values: a second solve with other targets is linear in them.
  const Eigen::MatrixX2d doubled = solver.solve(2.0 * targets);
  EXPECT_LT((doubled - 2.0 * control).norm(), 1e-9);
  EXPECT_THROW(solver.solve(targets.topRows(5)), std::invalid_argument);
}

TEST(FittingTest, BandedNormalEquationsRejectUndeterminedOrInvalidProblems) {
  const BSplineCurve truth = knownCurve();
  std::vector<double> clustered;
  for (int i = 0; i < 30; ++i) clustered.push_back(0.7 * i / 29.0);  // later points free
  EXPECT_THROW(CubicLeastSquares(truth, clustered), std::invalid_argument);
  EXPECT_THROW(CubicLeastSquares(truth, {2.0, 1.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(CubicLeastSquares(truth, {-1.0, 1.0}), std::invalid_argument);
  const BSplineCurve quadratic(2, {0, 0, 0, 1, 2, 2, 2}, {{0, 0}, {1, 1}, {2, 0}, {3, 1}});
  EXPECT_THROW(CubicLeastSquares(quadratic, {0.0, 0.5, 1.0, 1.5, 2.0}), std::invalid_argument);
}

TEST(FittingTest, RejectsUnderdeterminedOrInvalidProblems) {
  const BSplineCurve truth = knownCurve();
  std::vector<double> clustered;
  std::vector<Point2> points;
  for (int i = 0; i < 30; ++i) {  // all in the first span: later de Boor points are free
    clustered.push_back(0.7 * i / 29.0);
    points.push_back(truth.pointAt(clustered.back()));
  }
  EXPECT_THROW(leastSquaresFit(3, truth.knots(), points, clustered), std::invalid_argument);
  EXPECT_THROW(leastSquaresFit(3, truth.knots(), points, {0.0}), std::invalid_argument);
  EXPECT_THROW(leastSquaresFit(3, truth.knots(), {}, {}), std::invalid_argument);
  std::vector<Point2> with_nan = points;
  with_nan[3].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(leastSquaresFit(3, truth.knots(), with_nan, clustered), std::invalid_argument);
  std::vector<double> outside = clustered;
  outside[0] = -1.0;
  EXPECT_THROW(leastSquaresFit(3, truth.knots(), points, outside), std::invalid_argument);
  EXPECT_THROW(leastSquaresFit(3, {0, 1, 0.5}, points, clustered), std::invalid_argument);
  EXPECT_THROW(chordLengthParameters({{0, 0}}, 0.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace bspline
}  // namespace vicc_glyphs
